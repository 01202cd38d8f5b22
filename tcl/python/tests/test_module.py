# SPDX-License-Identifier: MIT
# The Python module against closed forms and against the same model in Tcl (through dabs.tcl in
# the module's own interpreter, or through the dabs program): conversions, return types, blocks,
# errors.
import array
import math
import threading

import pytest

import dabs
from conftest import run_program


def static_setup(system='BandGeneral'):
    dabs.constraints('Plain')
    dabs.numberer('Plain')
    dabs.system(system)
    dabs.test('NormDispIncr', 1.0e-12, 20)
    dabs.algorithm('Newton')
    dabs.integrator('LoadControl', 1.0)
    dabs.analysis('Static')


def test_every_command_of_the_table_is_a_function():
    assert len(dabs.commands) > 50
    for name in dabs.commands:
        fn = getattr(dabs, name)
        assert callable(fn) and fn.__name__ == name
        assert dabs.tcl('info commands ' + name) == name
    # The help text is the Tcl usage line.
    assert dabs.node.__doc__.startswith('node tag x')
    # A script sourced through dabs.tcl sees what `dabs script.tcl` with no arguments sees.
    assert dabs.tcl('list $argc $argv [package present dabs]') == '0 {} 0.1.0'
    # Tcl's own commands and variables are there; `wipe` leaves them, as in Tcl.
    dabs.tcl('proc twice {x} { return [expr {2 * $x}] }')
    dabs.wipe()
    assert dabs.tcl('twice 21') == '42'


def test_truss_and_zero_length_spring_against_closed_form():
    # Two bars (E A) from (0, 0) and (2a, 0) to the apex (a, h); a zero-length spring k in series
    # carries the vertical load P from node 4 to the apex.
    E, A, a, h, k, P = 2.0e8, 0.0004, 2.0, 1.5, 4.0e4, 60.0
    dabs.model('basic', '-ndm', 2, '-ndf', 2)
    dabs.node(1, 0.0, 0.0)
    dabs.node(2, 2 * a, 0.0)
    dabs.node(3, a, h)
    dabs.node(4, a, h)
    dabs.fix(1, 1, 1)
    dabs.fix(2, [1, 1])  # a list is spread into words, as OpenSeesPy reads it
    dabs.fix(4, 1, 0)
    dabs.uniaxialMaterial('Elastic', 1, E)
    dabs.uniaxialMaterial('Elastic', 2, k)
    dabs.element('truss', 1, 1, 3, A, 1)
    dabs.element('Truss', 2, 2, 3, A, 1)
    dabs.element('zeroLength', 3, 3, 4, '-mat', 2, '-dir', 2)
    dabs.timeSeries('Linear', 1)
    dabs.pattern('Plain', 1, 1)
    dabs.load(4, 0.0, -P)
    static_setup()
    assert dabs.analyze(1) == 0
    L = math.hypot(a, h)
    sin = h / L
    apex = -P * L / (2 * E * A * sin ** 2)
    assert dabs.nodeDisp(3, 2) == pytest.approx(apex, rel=1e-12)
    assert dabs.nodeDisp(3, 1) == pytest.approx(0.0, abs=1e-15)
    assert dabs.nodeDisp(4, 2) == pytest.approx(apex - P / k, rel=1e-12)
    assert dabs.eleResponse(1, 'axialForce') == pytest.approx([-P / (2 * sin)], rel=1e-12)
    assert dabs.eleResponse(3, 'force')[1] == pytest.approx(P, rel=1e-12)
    dabs.reactions()
    assert dabs.nodeReaction(1) == pytest.approx([P * a / (2 * h), P / 2], rel=1e-12)


def test_return_types_follow_openseespy():
    dabs.model('basic', '-ndm', 2, '-ndf', 3)
    dabs.node(1, 0.0, 0.0)
    dabs.node(2, 0.0, 3.0, '-mass', 2.0, 2.0, 0.0)
    dabs.fix(1, 1, 1, 1)
    dabs.geomTransf('Linear', 1)
    dabs.element('elasticBeamColumn', 1, 1, 2, 0.1, 2.0e8, 1.0e-3, 1)
    assert dabs.getNodeTags() == [1, 2] and all(type(t) is int for t in dabs.getNodeTags())
    assert dabs.getEleTags() == [1] and dabs.eleNodes(1) == [1, 2]
    assert dabs.getNDM() == [2] and dabs.getNDF() == [3]  # lists, as OpenSeesPy returns them
    disp = dabs.nodeDisp(2)
    assert type(disp) is list and len(disp) == 3 and all(type(v) is float for v in disp)
    assert type(dabs.nodeDisp(2, 1)) is float
    assert dabs.nodeCoord(2) == [0.0, 3.0] and dabs.nodeCoord(2, 2) == 3.0
    eig = dabs.eigen(1)
    assert type(eig) is list and len(eig) == 1 and type(eig[0]) is float
    # The closed form of a cantilever with a tip mass: lambda = 3 E I / (L^3 m).
    assert eig[0] == pytest.approx(3 * 2.0e8 * 1.0e-3 / (27.0 * 2.0), rel=1e-10)
    assert type(dabs.eleResponse(1, 'force')) is list
    dabs.timeSeries('Linear', 1)
    dabs.pattern('Plain', 1, 1)
    dabs.load(2, 1.0, 0.0, 0.0)
    dabs.integrator('Newmark', 0.5, 0.25)
    dabs.analysis('Transient')
    code = dabs.analyze(3, 0.1234567)
    assert type(code) is int and code == 0
    # getTime is the exact time (Tcl's default format has 6 decimals).
    assert type(dabs.getTime()) is float
    assert dabs.getTime() == float(dabs.tcl('getTime %.17g'))
    assert dabs.getTime() != round(dabs.getTime(), 6)
    assert type(dabs.version()) is str and dabs.version().endswith(dabs.__version__)
    stats = dabs.analysisStatistics()
    assert stats['steps'] == 3 and type(stats['iterations']) is int
    assert dabs.wipeAnalysis() is None
    dabs.wipe()
    assert dabs.getNodeTags() == [] and dabs.getEleTags() == []


def test_floats_keep_every_digit():
    dabs.model('basic', '-ndm', 1, '-ndf', 1)
    x = 0.1 + 0.2  # 0.30000000000000004: 17 significant digits
    dabs.node(1, x)
    assert dabs.nodeCoord(1, 1) == x
    dabs.node(2, 1e-300)
    assert dabs.nodeCoord(2, 1) == 1e-300


# The same fiber-section cantilever in Tcl: gravity, eigen, a short transient.
CANTILEVER_TCL = '''
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 0.0 2.5
node 3 0.0 5.0 -mass 12.0 12.0 0.0
fix 1 1 1 1
uniaxialMaterial Concrete02 1 -35000.0 -0.002 -7000.0 -0.006 0.1 2500.0 1.5e6
uniaxialMaterial Steel02 2 450000.0 2.0e8 0.01 18.0 0.925 0.15
section Fiber 1 {
  patch rect 1 12 1 -0.3 -0.25 0.3 0.25
  layer straight 2 4 0.0005 0.25 0.2 0.25 -0.2
  layer straight 2 4 0.0005 -0.25 0.2 -0.25 -0.2
  fiber 0.0 0.0 0.001 2
}
geomTransf PDelta 1
element forceBeamColumn 1 1 2 1 Lobatto 1 4
element dispBeamColumn 2 2 3 1 Legendre 1 3
timeSeries Linear 1
pattern Plain 1 1 { load 3 0.0 -500.0 0.0 }
constraints Transformation
numberer RCM
system SparseGeneral
test NormDispIncr 1.0e-12 30
algorithm Newton
integrator LoadControl 0.25
analysis Static
set out [list [analyze 4] [nodeDisp 3 2]]
loadConst -time 0.0
lappend out {*}[eigen 2]
wipeAnalysis
rayleigh 0.1 0.0 0.0 0.002
timeSeries Sine 2 0.0 1.0 0.25 -factor 3.0
pattern UniformExcitation 2 1 -accel 2
constraints Transformation
numberer RCM
system SparseGeneral
test NormDispIncr 1.0e-10 30
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
for {set i 0} {$i < 50} {incr i} {
  lappend out [analyze 1 0.01] [nodeDisp 3 1] [lindex [eleResponse 1 force] 2]
}
lappend out [getTime %.17g]
'''


def cantilever_python():
    out = []
    dabs.wipe()
    dabs.model('basic', '-ndm', 2, '-ndf', 3)
    dabs.node(1, 0.0, 0.0)
    dabs.node(2, 0.0, 2.5)
    dabs.node(3, 0.0, 5.0, '-mass', 12.0, 12.0, 0.0)
    dabs.fix(1, 1, 1, 1)
    dabs.uniaxialMaterial('Concrete02', 1, -35000.0, -0.002, -7000.0, -0.006, 0.1, 2500.0, 1.5e6)
    dabs.uniaxialMaterial('Steel02', 2, 450000.0, 2.0e8, 0.01, 18.0, 0.925, 0.15)
    dabs.section('Fiber', 1)
    dabs.patch('rect', 1, 12, 1, -0.3, -0.25, 0.3, 0.25)
    dabs.layer('straight', 2, 4, 0.0005, 0.25, 0.2, 0.25, -0.2)
    dabs.layer('straight', 2, 4, 0.0005, -0.25, 0.2, -0.25, -0.2)
    dabs.fiber(0.0, 0.0, 0.001, 2)
    dabs.geomTransf('PDelta', 1)
    dabs.element('forceBeamColumn', 1, 1, 2, 1, 'Lobatto', 1, 4)
    dabs.element('dispBeamColumn', 2, 2, 3, 1, 'Legendre', 1, 3)
    dabs.timeSeries('Linear', 1)
    dabs.pattern('Plain', 1, 1)
    dabs.load(3, 0.0, -500.0, 0.0)
    dabs.constraints('Transformation')
    dabs.numberer('RCM')
    dabs.system('SparseGeneral')
    dabs.test('NormDispIncr', 1.0e-12, 30)
    dabs.algorithm('Newton')
    dabs.integrator('LoadControl', 0.25)
    dabs.analysis('Static')
    out += [dabs.analyze(4), dabs.nodeDisp(3, 2)]
    dabs.loadConst('-time', 0.0)
    out += dabs.eigen(2)
    dabs.wipeAnalysis()
    dabs.rayleigh(0.1, 0.0, 0.0, 0.002)
    dabs.timeSeries('Sine', 2, 0.0, 1.0, 0.25, '-factor', 3.0)
    dabs.pattern('UniformExcitation', 2, 1, '-accel', 2)
    dabs.constraints('Transformation')
    dabs.numberer('RCM')
    dabs.system('SparseGeneral')
    dabs.test('NormDispIncr', 1.0e-10, 30)
    dabs.algorithm('Newton')
    dabs.integrator('Newmark', 0.5, 0.25)
    dabs.analysis('Transient')
    for _ in range(50):
        out += [dabs.analyze(1, 0.01), dabs.nodeDisp(3, 1), dabs.eleResponse(1, 'force')[2]]
    out.append(dabs.getTime())
    return out


def assert_same(python_values, tcl_values):
    assert len(python_values) == len(tcl_values)
    scale = max(abs(v) for v in tcl_values)
    for p, t in zip(python_values, tcl_values):
        assert p == pytest.approx(t, rel=1e-13, abs=1e-13 * scale)


def test_fiber_cantilever_matches_its_tcl_twin(tmp_path):
    python_values = cantilever_python()
    assert python_values[0] == 0 and python_values[1] < 0.0
    assert all(python_values[4 + 3 * i] == 0 for i in range(50))  # every step converged
    in_module = [float(v) for v in dabs.tcl(CANTILEVER_TCL + '\nset out').split()]
    assert_same(python_values, in_module)
    program = [float(v) for v in run_program(CANTILEVER_TCL + '\nputs $out\n', tmp_path).split()]
    assert_same(python_values, program)


def test_failed_command_raises_with_the_tcl_message_and_leaves_the_model():
    assert issubclass(dabs.OpenSeesError, Exception)
    dabs.model('basic', '-ndm', 2, '-ndf', 2)
    dabs.node(1, 0.0, 0.0)
    dabs.node(2, 1.0, 0.0)
    dabs.uniaxialMaterial('Elastic', 1, 100.0)
    tcl_message = dabs.tcl('catch {element truss 1 1 2 1.0 7} m; set m')
    with pytest.raises(dabs.OpenSeesError) as raised:
        dabs.element('truss', 1, 1, 2, 1.0, 7)
    assert str(raised.value) == tcl_message
    assert 'element truss 1' in tcl_message and '7' in tcl_message
    assert dabs.getEleTags() == []
    with pytest.raises(dabs.OpenSeesError, match='argument 2 \\(x\\) expected a number, got "abc"'):
        dabs.node(3, 'abc', 0.0)
    with pytest.raises(dabs.OpenSeesError, match='already exists'):
        dabs.node(2, 5.0, 5.0)
    assert dabs.getNodeTags() == [1, 2] and dabs.nodeCoord(2) == [1.0, 0.0]
    # Values Tcl has no form for, and keywords, are refused with the command and argument named.
    with pytest.raises(dabs.OpenSeesError, match='node: argument 2: expected a number'):
        dabs.node(3, None, 0.0)
    with pytest.raises(dabs.OpenSeesError, match='keyword'):
        dabs.node(3, 0.0, 0.0, mass=1.0)
    with pytest.raises(dabs.OpenSeesError, match='integer out of range'):
        dabs.node(2 ** 70, 0.0, 0.0)
    with pytest.raises(dabs.OpenSeesError, match='argument 1 \\(tag\\) expected an integer from'):
        dabs.node(2 ** 40, 0.0, 0.0)
    looped = [1.0]
    looped.append(looped)
    with pytest.raises(RecursionError):
        dabs.node(3, 0.0, looped)
    assert dabs.getNodeTags() == [1, 2]
    with pytest.raises(dabs.OpenSeesError, match='boom'):
        dabs.tcl('error boom')
    with pytest.raises(dabs.OpenSeesError, match='analyze: analysis is not defined'):
        dabs.analyze(1)


def test_section_block_is_the_tcl_body():
    dabs.model('basic', '-ndm', 2, '-ndf', 3)
    dabs.uniaxialMaterial('Elastic', 1, 2.0e8)
    dabs.section('Fiber', 1)
    dabs.patch('quad', 1, 4, 2, -0.2, -0.1, 0.2, -0.1, 0.2, 0.1, -0.2, 0.1)
    dabs.layer('circ', 1, 6, 0.001, 0.0, 0.0, 0.05)
    dabs.fiber(0.1, 0.0, 0.002, 1)
    dabs.tcl('section Fiber 2 { patch quad 1 4 2 -0.2 -0.1 0.2 -0.1 0.2 0.1 -0.2 0.1;'
             ' layer circ 1 6 0.001 0.0 0.0 0.05; fiber 0.1 0.0 0.002 1 }')
    # A body given as a Tcl script, as in Tcl, defines the section at once.
    dabs.section('Fiber', 3, '-noCentroid', 'fiber 0.0 0.0 0.01 1')
    assert 'section 3 already exists' in dabs.tcl('catch {section Fiber 3 {}} m; set m')
    # Two identical cantilevers on the two sections give the same tip displacement, bit for bit.
    dabs.geomTransf('Linear', 1)
    for k, sec in ((0, 1), (10, 2)):
        dabs.node(k + 1, 0.0, 0.0)
        dabs.node(k + 2, 2.0, 0.0)
        dabs.fix(k + 1, 1, 1, 1)
        dabs.element('forceBeamColumn', k + 1, k + 1, k + 2, 1, 'Lobatto', sec, 3)
    dabs.timeSeries('Linear', 1)
    dabs.pattern('Plain', 1, 1)
    dabs.load(2, 0.0, 20.0, 0.0)
    dabs.load(12, 0.0, 20.0, 0.0)
    static_setup()
    assert dabs.analyze(1) == 0
    assert dabs.nodeDisp(2, 2) == dabs.nodeDisp(12, 2) and dabs.nodeDisp(2, 2) > 0.0


def test_error_in_a_section_block_surfaces_where_the_block_closes():
    dabs.model('basic', '-ndm', 2, '-ndf', 3)
    dabs.uniaxialMaterial('Elastic', 1, 100.0)
    dabs.section('Fiber', 5)
    dabs.patch('rect', 99, 2, 2, -0.1, -0.1, 0.1, 0.1)  # no material 99: found when the block closes
    with pytest.raises(dabs.OpenSeesError) as raised:
        dabs.node(1, 0.0, 0.0)
    tcl_message = dabs.tcl('catch {section Fiber 5 { patch rect 99 2 2 -0.1 -0.1 0.1 0.1 }} m; set m')
    assert str(raised.value) == (tcl_message + ' (the section block was closed by the call of node,'
                                 ' which was not run)')
    assert 'section Fiber 5' in tcl_message and '99' in tcl_message
    assert dabs.getNodeTags() == []  # the closing call was not run either
    dabs.section('Fiber', 5)  # the failed section was not defined: its tag is free
    dabs.fiber(0.0, 0.0, 0.01, 1)
    assert dabs.node(1, 0.0, 0.0) is None
    with pytest.raises(dabs.OpenSeesError, match='only valid inside a section Fiber body'):
        dabs.patch('rect', 1, 2, 2, -0.1, -0.1, 0.1, 0.1)
    # A repeated tag is refused with Tcl's message when the block closes.
    dabs.section('Fiber', 5)
    dabs.fiber(0.0, 0.0, 0.01, 1)
    with pytest.raises(dabs.OpenSeesError, match='section 5 already exists'):
        dabs.getNodeTags()


PATTERNS_TCL = '''
model basic -ndm 2 -ndf 3
node 1 0.0 0.0; node 2 4.0 0.0; node 3 8.0 0.0
fix 1 1 1 1; fix 3 0 1 0
geomTransf Linear 1
element elasticBeamColumn 1 1 2 0.02 2.0e8 2.0e-4 1
element elasticBeamColumn 2 2 3 0.02 2.0e8 2.0e-4 1
timeSeries Linear 1
pattern Plain 1 1 -fact 2.0 {
  load 2 0.0 -10.0 0.0
  sp 3 1 0.001
  eleLoad -ele 1 2 -type -beamUniform -3.0
}
constraints Transformation; numberer Plain; system BandGeneral
test NormDispIncr 1.0e-12 10; algorithm Newton; integrator LoadControl 0.5; analysis Static
analyze 2
list {*}[nodeDisp 2] {*}[nodeDisp 3] {*}[eleResponse 1 localForce]
'''


def test_pattern_then_loads_is_the_tcl_body():
    tcl_values = [float(v) for v in dabs.tcl(PATTERNS_TCL).split()]
    dabs.wipe()
    dabs.model('basic', '-ndm', 2, '-ndf', 3)
    dabs.node(1, 0.0, 0.0)
    dabs.node(2, 4.0, 0.0)
    dabs.node(3, 8.0, 0.0)
    dabs.fix(1, 1, 1, 1)
    dabs.fix(3, 0, 1, 0)
    dabs.geomTransf('Linear', 1)
    dabs.element('elasticBeamColumn', 1, 1, 2, 0.02, 2.0e8, 2.0e-4, 1)
    dabs.element('elasticBeamColumn', 2, 2, 3, 0.02, 2.0e8, 2.0e-4, 1)
    dabs.timeSeries('Linear', 1)
    dabs.pattern('Plain', 1, 1, '-fact', 2.0)
    dabs.load(2, 0.0, -10.0, 0.0)
    dabs.sp(3, 1, 0.001)
    dabs.eleLoad('-ele', 1, 2, '-type', '-beamUniform', -3.0)
    dabs.constraints('Transformation')
    dabs.numberer('Plain')
    dabs.system('BandGeneral')
    dabs.test('NormDispIncr', 1.0e-12, 10)
    dabs.algorithm('Newton')
    dabs.integrator('LoadControl', 0.5)
    dabs.analysis('Static')
    assert dabs.analyze(2) == 0
    python_values = dabs.nodeDisp(2) + dabs.nodeDisp(3) + dabs.eleResponse(1, 'localForce')
    assert python_values == tcl_values
    assert dabs.nodeDisp(3, 1) == pytest.approx(2 * 0.001, rel=1e-12)  # the sp, times -fact


MULTIPLE_TCL = '''
model basic -ndm 1 -ndf 1
node 1 0.0; node 2 1.0; node 3 2.0
fix 1 1; fix 3 1
mass 2 3.0
uniaxialMaterial Elastic 1 400.0
element zeroLength 1 1 2 -mat 1 -dir 1
element zeroLength 2 2 3 -mat 1 -dir 1
timeSeries Sine 1 0.0 10.0 0.5 -factor 0.02
timeSeries Path 2 -dt 0.05 -values {0.0 0.001 0.003 0.004 0.0045 0.005}
pattern MultipleSupport 1 {
  groundMotion 1 Plain -disp 1
  groundMotion 2 Plain -disp 2
  imposedMotion 1 1 1
  imposedMotion 3 1 2
}
constraints Transformation; numberer Plain; system BandGeneral
test NormDispIncr 1.0e-12 10; algorithm Newton; integrator Newmark 0.5 0.25; analysis Transient
set out {}
for {set i 0} {$i < 20} {incr i} { analyze 1 0.02; lappend out [nodeDisp 1 1] [nodeDisp 2 1] [nodeDisp 3 1] }
set out
'''


def test_multiple_support_then_motions_is_the_tcl_body():
    tcl_values = [float(v) for v in dabs.tcl(MULTIPLE_TCL).split()]
    dabs.wipe()
    dabs.model('basic', '-ndm', 1, '-ndf', 1)
    dabs.node(1, 0.0)
    dabs.node(2, 1.0)
    dabs.node(3, 2.0)
    dabs.fix(1, 1)
    dabs.fix(3, 1)
    dabs.mass(2, 3.0)
    dabs.uniaxialMaterial('Elastic', 1, 400.0)
    dabs.element('zeroLength', 1, 1, 2, '-mat', 1, '-dir', 1)
    dabs.element('zeroLength', 2, 2, 3, '-mat', 1, '-dir', 1)
    dabs.timeSeries('Sine', 1, 0.0, 10.0, 0.5, '-factor', 0.02)
    dabs.timeSeries('Path', 2, '-dt', 0.05, '-values', 0.0, 0.001, 0.003, 0.004, 0.0045, 0.005)
    dabs.pattern('MultipleSupport', 1)
    dabs.groundMotion(1, 'Plain', '-disp', 1)
    dabs.groundMotion(2, 'Plain', '-disp', 2)
    dabs.imposedMotion(1, 1, 1)
    dabs.imposedMotion(3, 1, 2)
    dabs.constraints('Transformation')
    dabs.numberer('Plain')
    dabs.system('BandGeneral')
    dabs.test('NormDispIncr', 1.0e-12, 10)
    dabs.algorithm('Newton')
    dabs.integrator('Newmark', 0.5, 0.25)
    dabs.analysis('Transient')
    out = []
    for _ in range(20):
        dabs.analyze(1, 0.02)
        out += [dabs.nodeDisp(1, 1), dabs.nodeDisp(2, 1), dabs.nodeDisp(3, 1)]
    assert out == tcl_values
    assert out[3 * 9 + 2] == pytest.approx(0.0045, rel=1e-9)  # support 3 follows its record
    assert out[-3] == pytest.approx(0.02 * math.sin(2 * math.pi * 0.4 / 0.5), rel=1e-9)


def test_path_values_as_words_or_as_a_list():
    dabs.model('basic', '-ndm', 1, '-ndf', 1)
    values = [0.0, 0.25, 1.0, 2.25]
    dabs.timeSeries('Path', 1, '-dt', 0.5, '-values', *values)
    dabs.timeSeries('Path', 2, '-dt', 0.5, '-values', values)
    dabs.timeSeries('Path', 3, '-time', [0.0, 0.5, 1.0, 1.5], '-values', values)
    # Any sequence of numbers (array.array here, a numpy array alike) is a list.
    dabs.timeSeries('Path', 4, '-dt', 0.5, '-values', array.array('d', values))
    for tag in (1, 2, 3, 4):
        dabs.pattern('Plain', tag, tag)
    dabs.setTime(1.25)
    assert [dabs.getLoadFactor(t) for t in (1, 2, 3, 4)] == [1.625] * 4
    dabs.node(1, 0.0)
    dabs.fix(1, range(1, 2))  # spread into words like a list
    dabs.node(2, 1.0)
    dabs.fix(2, (1,))
    assert dabs.tcl('llength [getNodeTags]') == '2'


def test_only_the_importing_thread_may_call():
    errors = []

    def call():
        try:
            dabs.getNodeTags()
        except dabs.OpenSeesError as e:
            errors.append(str(e))

    t = threading.Thread(target=call)
    t.start()
    t.join()
    assert len(errors) == 1 and 'thread' in errors[0]


def test_analyze_lets_other_python_threads_run():
    dabs.model('basic', '-ndm', 2, '-ndf', 3)
    dabs.geomTransf('Linear', 1)
    dabs.node(0, 0.0, 0.0)
    dabs.fix(0, 1, 1, 1)
    for i in range(1, 41):
        dabs.node(i, 0.0, 0.5 * i, '-mass', 1.0, 1.0, 0.01)
        dabs.element('elasticBeamColumn', i, i - 1, i, 0.1, 2.0e8, 1.0e-3, 1)
    dabs.timeSeries('Sine', 1, 0.0, 100.0, 0.3)
    dabs.pattern('UniformExcitation', 1, 1, '-accel', 1)
    dabs.constraints('Plain')
    dabs.numberer('RCM')
    dabs.system('BandGeneral')
    dabs.test('NormDispIncr', 1.0e-10, 10)
    dabs.algorithm('Newton')
    dabs.integrator('Newmark', 0.5, 0.25)
    dabs.analysis('Transient')
    count = [0]
    done = threading.Event()

    def spin():
        while not done.is_set():
            count[0] += 1

    t = threading.Thread(target=spin)
    t.start()
    try:
        before = count[0]
        assert dabs.analyze(3000, 0.001) == 0
        during = count[0] - before
    finally:
        done.set()
        t.join()
    assert during > 1000


def test_threads_and_dabs_threads_work_as_in_tcl():
    import os
    import subprocess
    import sys
    script = 'import dabs; print(dabs.threads()); dabs.threads(1); print(dabs.threads())'
    done = subprocess.run([sys.executable, '-c', script], capture_output=True, text=True,
                          timeout=60, env=dict(os.environ, DABS_THREADS='2'))
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ['2', '1']
    with pytest.raises(dabs.OpenSeesError, match='threads: argument 1 \\(n\\).*must be 1 to 256'):
        dabs.threads(0)


def test_python_and_tcl_output_keep_call_order():
    import os
    import subprocess
    import sys
    script = ('import dabs\n'
              'print("a")\n'
              'dabs.tcl("puts b")\n'
              'print("c")\n'
              'dabs.model("basic", "-ndm", 1, "-ndf", 1)\n'
              'dabs.node(7, 0.5)\n'
              'dabs.printModel("-node", 7)\n'
              'print("d")\n')
    done = subprocess.run([sys.executable, '-c', script], capture_output=True, text=True,
                          timeout=60, env=dict(os.environ))
    assert done.returncode == 0, done.stderr
    lines = [line for line in done.stdout.splitlines() if line.strip()]
    assert lines[:3] == ['a', 'b', 'c'] and lines[-1] == 'd'
    assert any('7' in line for line in lines[3:-1])  # the node's print between c and d


def test_calls_after_shutdown_raise_instead_of_crashing():
    import subprocess
    import sys
    script = ('import dabs\n'
              'dabs._shutdown()\n'
              'for call in (lambda: dabs.getNodeTags(), lambda: dabs.tcl("set x 1")):\n'
              '    try:\n'
              '        call()\n'
              '    except dabs.OpenSeesError as e:\n'
              '        print(e)\n')
    done = subprocess.run([sys.executable, '-c', script], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == ['dabs: the module was shut down'] * 2


def test_pounding_takes_its_node_lists_as_lists():
    # Two girder end faces 10 mm apart; every node of each face contacts the other face.
    dabs.model('basic', '-ndm', 3, '-ndf', 3)
    corners = [(-1.0, -0.5), (1.0, -0.5), (1.0, 0.5), (-1.0, 0.5)]
    for i, (y, z) in enumerate(corners, start=1):
        dabs.node(10 + i, 0.0, y, z)
        dabs.node(20 + i, 0.01, y, z)
    made = dabs.pounding(100, '-side1', [11, 12, 13, 14], (11, 12, 13, 14),
                         '-side2', [21, 22, 23, 24], [21, 24, 23, 22], '-K', 1.0e6)
    assert made == list(range(100, 108))
    python_nodes = [dabs.eleNodes(e) for e in made]
    assert python_nodes[0][0] == 11 and dabs.eleResponse(100, 'gap') == [pytest.approx(0.01)]
    # The Tcl twin: the same pairs on the same nodes.
    dabs.wipe()
    tcl = dabs.tcl('model basic -ndm 3 -ndf 3\n'
                   'foreach i {1 2 3 4} y {-1.0 1.0 1.0 -1.0} z {-0.5 -0.5 0.5 0.5} {\n'
                   '  node [expr {10 + $i}] 0.0 $y $z; node [expr {20 + $i}] 0.01 $y $z\n'
                   '}\n'
                   'pounding 100 -side1 {11 12 13 14} {11 12 13 14}'
                   ' -side2 {21 22 23 24} {21 24 23 22} -K 1.0e6\n'
                   'lmap e [getEleTags] { eleNodes $e }')
    assert [[int(n) for n in group.split()] for group in tcl.strip('{}').split('} {')] == \
        python_nodes
