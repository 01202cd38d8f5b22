# SPDX-License-Identifier: MIT
# The Python type of what each query returns (float, int, str, None, or a list and the types of
# its items), for a small cantilever: run through OpenSeesPy it wrote
# reference/return-types-openseespy.txt, and the dabs module must give the same types
# (test_twins.py). Usage: python3 return_types.py dabs|opensees
import importlib
import sys


def type_name(value):
    if isinstance(value, list):
        items = ','.join(sorted({type(x).__name__ for x in value}))
        return 'list[%s] len %d' % (items, len(value))
    return type(value).__name__


def types(ops):
    ops.wipe()
    ops.model('basic', '-ndm', 2, '-ndf', 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 3.0)
    ops.mass(2, 2.0, 2.0, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.geomTransf('Linear', 1)
    ops.element('elasticBeamColumn', 1, 1, 2, 0.1, 2.0e8, 1.0e-3, 1)
    ops.timeSeries('Linear', 1)
    ops.pattern('Plain', 1, 1)
    ops.load(2, 1.0, 0.0, 0.0)
    ops.integrator('Newmark', 0.5, 0.25)
    ops.analysis('Transient')
    calls = [
        ('eigen', lambda: ops.eigen(1)),
        ('analyze', lambda: ops.analyze(2, 0.01)),
        ('nodeDisp', lambda: ops.nodeDisp(2)),
        ('nodeDisp dof', lambda: ops.nodeDisp(2, 1)),
        ('nodeVel dof', lambda: ops.nodeVel(2, 1)),
        ('nodeAccel', lambda: ops.nodeAccel(2)),
        ('getTime', ops.getTime),
        ('getNodeTags', ops.getNodeTags),
        ('getEleTags', ops.getEleTags),
        ('eleNodes', lambda: ops.eleNodes(1)),
        ('eleResponse', lambda: ops.eleResponse(1, 'force')),
        ('eleForce', lambda: ops.eleForce(1)),
        ('eleForce dof', lambda: ops.eleForce(1, 1)),
        ('nodeCoord', lambda: ops.nodeCoord(2)),
        ('nodeCoord dof', lambda: ops.nodeCoord(2, 2)),
        ('getNDM', ops.getNDM),
        ('getNDF', ops.getNDF),
        ('testIter', ops.testIter),
        ('getLoadFactor', lambda: ops.getLoadFactor(1)),
        ('nodeMass', lambda: ops.nodeMass(2)),
        ('nodeEigenvector', lambda: ops.nodeEigenvector(2, 1)),
        ('reactions', ops.reactions),
        ('nodeReaction', lambda: ops.nodeReaction(1)),
        ('nodeReaction dof', lambda: ops.nodeReaction(1, 2)),
        ('version', ops.version),
        ('wipeAnalysis', ops.wipeAnalysis),
        ('node', lambda: ops.node(3, 1.0, 1.0)),
    ]
    return [(name, type_name(call())) for name, call in calls]


if __name__ == '__main__':
    for name, kind in types(importlib.import_module(sys.argv[1])):
        print('%s: %s' % (name, kind))
