# SPDX-License-Identifier: MIT
# Loads and supports written for the Python module: a two-span continuous beam (displacement-based
# elements on an elastic section) under member loads (uniform and point) and a settlement of its middle
# support (sp, the support's only restraint), then a spring chain whose two supports move by a MultipleSupport pattern
# (one Path record given as words, one as a list). supports.tcl is its Tcl twin. run(ops) returns
# the printed rows. Units kN, m, s, t.


def run(ops):
    rows = []
    ops.wipe()
    ops.model('basic', '-ndm', 2, '-ndf', 3)
    for i in range(5):
        ops.node(i + 1, 3.0 * i, 0.0)
    ops.fix(1, 1, 1, 0)
    ops.fix(5, 0, 1, 0)
    ops.section('Elastic', 1, 3.0e7, 0.12, 1.6e-3)
    ops.geomTransf('Linear', 1)
    ops.beamIntegration('Legendre', 1, 1, 3)
    for e in range(1, 5):
        ops.element('dispBeamColumn', e, e, e + 1, 1, 1)
    ops.timeSeries('Linear', 1)
    ops.pattern('Plain', 1, 1)
    ops.eleLoad('-ele', 1, 2, '-type', '-beamUniform', -12.0)
    ops.eleLoad('-range', 3, 4, '-type', '-beamPoint', -30.0, 0.4)
    ops.sp(3, 2, -0.002)
    ops.load(5, 5.0, 0.0, 0.0)
    ops.constraints('Transformation')
    ops.numberer('RCM')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-12, 10)
    ops.algorithm('Newton')
    ops.integrator('LoadControl', 0.5)
    ops.analysis('Static')
    rows.append(['beamStatus', ops.analyze(2)])
    rows.append(['beamDisp', ops.nodeDisp(2, 2), ops.nodeDisp(3, 2), ops.nodeDisp(4, 2),
                 ops.nodeDisp(5, 1), ops.nodeDisp(1, 3)])
    rows.append(['beamForces'] + ops.eleResponse(2, 'localForce') + ops.eleResponse(3, 'localForce'))
    ops.reactions()
    rows.append(['beamReactions', ops.nodeReaction(1, 2), ops.nodeReaction(3, 2),
                 ops.nodeReaction(5, 2)])

    ops.wipe()
    ops.model('basic', '-ndm', 1, '-ndf', 1)
    ops.node(1, 0.0)
    ops.node(2, 0.0, '-mass', 2.0)
    ops.node(3, 0.0, '-mass', 1.0)
    ops.node(4, 0.0)
    ops.fix(1, 1)
    ops.fix(4, 1)
    ops.uniaxialMaterial('Elastic', 1, 300.0)
    ops.uniaxialMaterial('Elastic', 2, 150.0, 2.0)
    ops.element('zeroLength', 1, 1, 2, '-mat', 1, '-dir', 1)
    ops.element('zeroLength', 2, 2, 3, '-mat', 2, '-dir', 1)
    ops.element('zeroLength', 3, 3, 4, '-mat', 1, '-dir', 1)
    left = [0.0, 0.004, 0.010, 0.013, 0.011, 0.006, 0.002, 0.0, -0.001, 0.0]
    right = [0.0, -0.002, -0.003, 0.001, 0.006, 0.008, 0.007, 0.004, 0.002, 0.0]
    ops.timeSeries('Path', 1, '-dt', 0.1, '-values', *left)
    ops.timeSeries('Path', 2, '-dt', 0.1, '-values', right)
    ops.pattern('MultipleSupport', 1)
    ops.groundMotion(1, 'Plain', '-disp', 1)
    ops.groundMotion(2, 'Plain', '-disp', 2)
    ops.imposedMotion(1, 1, 1)
    ops.imposedMotion(4, 1, 2)
    ops.constraints('Transformation')
    ops.numberer('Plain')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-12, 10)
    ops.algorithm('Newton')
    ops.integrator('Newmark', 0.5, 0.25)
    ops.analysis('Transient')
    for step in range(1, 61):
        status = ops.analyze(1, 0.02)
        if status != 0:
            rows.append(['failed', step, status])
            break
        if step % 5 == 0:
            rows.append(['chain', step, ops.nodeDisp(1, 1), ops.nodeDisp(2, 1), ops.nodeDisp(3, 1),
                         ops.nodeDisp(4, 1), ops.nodeVel(2, 1), ops.eleResponse(2, 'force')[1]])
    return rows


if __name__ == '__main__':
    from twin import main
    main(run)
