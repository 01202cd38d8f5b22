# SPDX-License-Identifier: MIT
# Writes the rows of one of these scripts as CSV, run through the module named on the command line:
#   PYTHONPATH=<dir of OpenSeesPy's opensees.so>:. python3 make-reference.py opensees frame > reference/frame-openseespy.csv
# (the reference files were made so with OpenSeesPy built from OpenSees' public source; see README.md).
import importlib
import sys

module_name, script = sys.argv[1], sys.argv[2]
ops = importlib.import_module(module_name)
rows = importlib.import_module(script).run(ops)
print('# rows of verification/python/%s.py run through %s (%s)' % (script, module_name,
                                                                   getattr(ops, '__file__', '?').split('/')[-1]))
print('# made by: PYTHONPATH=<dir of opensees.so>:. python3 make-reference.py %s %s' % (module_name, script))
for row in rows:
    print(','.join(repr(v) if isinstance(v, float) else str(v) for v in row))
