# SPDX-License-Identifier: MIT
# A one-bay RC portal frame with fiber-section force-based columns, written for the Python module:
# gravity by load control, two eigenvalues, then 2 s of a sine ground acceleration (Newmark,
# Rayleigh damping). frame.tcl is its Tcl twin, word for word. Units kN, m, s, t.
# run(ops) takes the module (dabs, or OpenSeesPy's opensees for the reference numbers) and returns
# the rows printed: a label and numbers.


def run(ops):
    rows = []
    ops.wipe()
    ops.model('basic', '-ndm', 2, '-ndf', 3)
    height, span = 4.0, 6.0
    ops.node(1, 0.0, 0.0)
    ops.node(2, span, 0.0)
    ops.node(3, 0.0, height)
    ops.node(4, span, height)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    ops.mass(3, 20.0, 20.0, 0.0)
    ops.mass(4, 20.0, 20.0, 0.0)
    ops.uniaxialMaterial('Concrete01', 1, -32000.0, -0.0022, -7000.0, -0.008)  # confined core
    ops.uniaxialMaterial('Concrete01', 2, -27000.0, -0.002, -5000.0, -0.0045)  # cover
    ops.uniaxialMaterial('Steel01', 3, 440000.0, 2.0e8, 0.015)
    b, h, cover, bar = 0.35, 0.45, 0.04, 0.00049
    y1, z1 = h / 2.0, b / 2.0
    ops.section('Fiber', 1)
    ops.patch('rect', 1, 10, 1, cover - y1, cover - z1, y1 - cover, z1 - cover)
    ops.patch('rect', 2, 10, 1, -y1, -z1, y1, cover - z1)
    ops.patch('rect', 2, 10, 1, -y1, z1 - cover, y1, z1)
    ops.patch('rect', 2, 2, 1, -y1, cover - z1, cover - y1, z1 - cover)
    ops.patch('rect', 2, 2, 1, y1 - cover, cover - z1, y1, z1 - cover)
    ops.layer('straight', 3, 3, bar, y1 - cover, z1 - cover, y1 - cover, cover - z1)
    ops.layer('straight', 3, 2, bar, 0.0, z1 - cover, 0.0, cover - z1)
    ops.layer('straight', 3, 3, bar, cover - y1, z1 - cover, cover - y1, cover - z1)
    ops.geomTransf('PDelta', 1)
    ops.geomTransf('Linear', 2)
    ops.beamIntegration('Lobatto', 1, 1, 5)
    ops.element('forceBeamColumn', 1, 1, 3, 1, 1)
    ops.element('forceBeamColumn', 2, 2, 4, 1, 1)
    ops.element('elasticBeamColumn', 3, 3, 4, 0.3, 3.0e7, 0.0064, 2)

    ops.timeSeries('Linear', 1)
    ops.pattern('Plain', 1, 1)
    ops.load(3, 0.0, -350.0, 0.0)
    ops.load(4, 0.0, -350.0, 0.0)
    ops.constraints('Plain')
    ops.numberer('Plain')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-12, 25)
    ops.algorithm('Newton')
    ops.integrator('LoadControl', 0.1)
    ops.analysis('Static')
    rows.append(['gravityStatus', ops.analyze(10)])
    rows.append(['gravity', ops.nodeDisp(3, 1), ops.nodeDisp(3, 2), ops.nodeDisp(4, 2),
                 ops.nodeDisp(3, 3)])
    ops.loadConst('-time', 0.0)
    rows.append(['eigen'] + list(ops.eigen(2)))

    ops.wipeAnalysis()
    ops.rayleigh(0.25, 0.0, 0.003, 0.0)
    ops.timeSeries('Trig', 2, 0.0, 2.0, 0.4, '-factor', 4.0)
    ops.pattern('UniformExcitation', 2, 1, '-accel', 2)
    ops.constraints('Plain')
    ops.numberer('Plain')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-10, 50)
    ops.algorithm('Newton')
    ops.integrator('Newmark', 0.5, 0.25)
    ops.analysis('Transient')
    for step in range(1, 201):
        status = ops.analyze(1, 0.01)
        if status != 0:
            rows.append(['failed', step, status])
            break
        if step % 20 == 0:
            force = ops.eleResponse(1, 'force')
            rows.append(['step', step, ops.nodeDisp(3, 1), ops.nodeDisp(4, 1), ops.nodeVel(3, 1),
                         force[0], force[1], force[2]])
    return rows


if __name__ == '__main__':
    from twin import main
    main(run)
