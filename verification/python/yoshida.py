# SPDX-License-Identifier: MIT
# A high-damping rubber bearing written for the Python module: a yoshidaBearing (HDR set (a) of
# verification/bearing/fitted-parameters.md) under a vertical load, driven around a growing
# figure-of-eight orbit by imposed displacements (Path series). yoshida.tcl is its Tcl twin.
# run(ops) returns the printed rows. Units kN, m.
import math


def run(ops):
    rows = []
    area, rubber = 0.64, 0.16
    y0, u0, n, a0, b, q, g = 0.435794, 0.0683367, 0.115167, 0.831926, 0.698464, 0.0393774, 0.000947439
    ops.wipe()
    ops.model('basic', '-ndm', 3, '-ndf', 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 0.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.fix(2, 0, 0, 0, 1, 1, 1)
    ops.biaxialMaterial('Yoshida', 1, y0 * 1000.0 * area, u0 * rubber, n, a0, b, q, g)
    ops.element('yoshidaBearing', 1, 1, 2, 1, '-Tr', rubber, '-Kv', 2.0e6, '-limits', 2.5, 3.0)
    steps = 240
    xs = [0.0] + [0.3 * rubber * (1 + i / steps) * math.sin(2 * math.pi * i / 80) for i in range(1, steps + 1)]
    ys = [0.0] + [0.2 * rubber * (1 + i / steps) * math.sin(4 * math.pi * i / 80) for i in range(1, steps + 1)]
    ops.timeSeries('Path', 1, '-dt', 1.0, '-values', *xs)  # OpenSeesPy's form: values as words
    ops.timeSeries('Path', 2, '-dt', 1.0, '-values', ys)  # or one list
    ops.timeSeries('Constant', 3)
    ops.pattern('Plain', 1, 1)
    ops.sp(2, 1, 1.0)
    ops.pattern('Plain', 2, 2)
    ops.sp(2, 2, 1.0)
    ops.pattern('Plain', 3, 3)
    ops.load(2, 0.0, 0.0, -800.0, 0.0, 0.0, 0.0)
    ops.constraints('Transformation')
    ops.numberer('Plain')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-11, 30)
    ops.algorithm('Newton')
    ops.integrator('LoadControl', 1.0)
    ops.analysis('Static')
    for step in range(1, steps + 1):
        status = ops.analyze(1)
        if status != 0:
            rows.append(['failed', step, status])
            break
        if step % 10 == 0:
            f = ops.eleResponse(1, 'basicForce')
            rows.append(['step', step, ops.nodeDisp(2, 1), ops.nodeDisp(2, 2), ops.nodeDisp(2, 3),
                         f[0], f[1], f[2], *ops.eleResponse(1, 'shearStrain')])
    rows.append(['energy', *ops.eleResponse(1, 'dissipatedEnergy'),
                 *ops.eleResponse(1, 'maxShearStrain')])
    return rows


if __name__ == '__main__':
    from twin import main
    main(run)
