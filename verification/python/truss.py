# SPDX-License-Identifier: MIT
# A zero-length spring in series with a two-bar truss, written for the Python module: a static
# load, then load cycles past yield of an yielding (Steel01) spring (displacement control).
# truss.tcl is its Tcl twin. run(ops) takes dabs (or OpenSeesPy's opensees for the reference
# numbers) and returns the printed rows. Units kN, m.


def run(ops):
    rows = []
    ops.wipe()
    ops.model('basic', '-ndm', 2, '-ndf', 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 4.0, 0.0)
    ops.node(3, 2.0, 1.5)
    ops.node(4, 2.0, 1.5)
    ops.fix(1, 1, 1)
    ops.fix(2, 1, 1)
    ops.uniaxialMaterial('Elastic', 1, 2.0e8)
    ops.uniaxialMaterial('Steel01', 2, 80.0, 5.0e4, 0.05)
    ops.uniaxialMaterial('Elastic', 3, 1.0e9)
    ops.element('truss', 1, 1, 3, 0.0004, 1)
    ops.element('truss', 2, 2, 3, 0.0004, 1)
    ops.element('zeroLength', 3, 3, 4, '-mat', 2, 3, '-dir', 1, 2)
    ops.timeSeries('Linear', 1)
    ops.pattern('Plain', 1, 1)
    ops.load(4, 0.0, -60.0)
    ops.constraints('Plain')
    ops.numberer('RCM')
    ops.system('BandSPD')
    ops.test('NormUnbalance', 1.0e-9, 10)
    ops.algorithm('Newton')
    ops.integrator('LoadControl', 1.0)
    ops.analysis('Static')
    rows.append(['static', ops.analyze(1), ops.nodeDisp(3, 2), ops.nodeDisp(4, 2),
                 ops.eleResponse(1, 'axialForce')[0], ops.eleResponse(2, 'axialForce')[0]])
    ops.loadConst('-time', 0.0)
    ops.wipeAnalysis()
    ops.pattern('Plain', 2, 1)
    ops.load(4, 1.0, 0.0)
    ops.constraints('Plain')
    ops.numberer('RCM')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-12, 20)
    ops.algorithm('Newton')
    for target in (0.006, -0.006, 0.008):
        steps = 8
        increment = (target - ops.nodeDisp(4, 1)) / steps
        ops.integrator('DisplacementControl', 4, 1, increment)
        ops.analysis('Static')
        for _ in range(steps):
            status = ops.analyze(1)
            rows.append(['cycle', status, ops.nodeDisp(4, 1), ops.nodeDisp(3, 1),
                         ops.getLoadFactor(2), ops.eleResponse(3, 'force')[0]])
    ops.reactions()
    rows.append(['reactions', ops.nodeReaction(1, 1), ops.nodeReaction(1, 2),
                 ops.nodeReaction(2, 1), ops.nodeReaction(2, 2)])
    return rows


if __name__ == '__main__':
    from twin import main
    main(run)
