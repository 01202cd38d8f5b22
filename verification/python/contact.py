# SPDX-License-Identifier: MIT
# A contact pair written for the Python module: a 2 t block pushed obliquely onto a fixed square
# face (nodeToSurface, Kelvin law with restitution, Coulomb friction), so that it strikes, slides,
# bounces and comes back. contact.tcl is its Tcl twin. run(ops) returns the printed rows.
# Units kN, m, s, t.


def run(ops):
    rows = []
    ops.wipe()
    ops.model('basic', '-ndm', 3, '-ndf', 3)
    ops.node(1, 0.0, -1.0, -1.0)
    ops.node(2, 0.0, -1.0, 1.0)
    ops.node(3, 0.0, 1.0, 1.0)
    ops.node(4, 0.0, 1.0, -1.0)
    ops.node(5, -0.02, 0.0, 0.0, '-mass', 2.0, 2.0, 2.0)
    for n in (1, 2, 3, 4):
        ops.fix(n, 1, 1, 1)
    ops.fix(5, 0, 0, 1)
    ops.element('nodeToSurface', 1, 5, 1, 2, 3, 4, '-K', 4.0e5, '-e', 0.7, '-mu_s', 0.3,
                '-mu_k', 0.25, '-Kt', 2.0e5, '-masses', 2.0, 1.0e6)
    ops.timeSeries('Rectangular', 1, 0.0, 0.15)
    ops.pattern('Plain', 1, 1)
    ops.load(5, 30.0, 12.0, 0.0)
    ops.constraints('Plain')
    ops.numberer('Plain')
    ops.system('FullGeneral')
    ops.test('NormDispIncr', 1.0e-12, 50)
    ops.algorithm('Newton')
    ops.integrator('Newmark', 0.5, 0.25)
    ops.analysis('Transient')
    for step in range(1, 301):
        status = ops.analyze(1, 0.001)
        if status != 0:
            rows.append(['failed', step, status])
            break
        if step % 15 == 0:
            rows.append(['step', step, ops.nodeDisp(5, 1), ops.nodeDisp(5, 2), ops.nodeVel(5, 1),
                         *ops.eleResponse(1, 'gap'), *ops.eleResponse(1, 'contactForce'),
                         *ops.eleResponse(1, 'status')])
    rows.append(['energy', *ops.eleResponse(1, 'dissipatedEnergy'),
                 *ops.eleResponse(1, 'impulse')])
    return rows


if __name__ == '__main__':
    from twin import main
    main(run)
