# SPDX-License-Identifier: MIT
"""The bridge case study's pound case run from Python through the dabs module.

bridge.tcl is sourced as a library (::bridgeLibraryOnly), its runCase runs the case in the
module's interpreter, and the joint gap histories it writes are plotted with matplotlib when that
is installed.

    PYTHONPATH=build/python python3 verification/bridge/bridge.py ?--duration s? ?--out dir? ?--motion m?

Prints the run's completion, its peak joint gaps and the plot's path (or why there is none).
"""
import argparse
import csv
import pathlib
import sys

import dabs

HERE = pathlib.Path(__file__).resolve().parent


def run_pound(duration, out_dir, motion='auto'):
    """Runs the pound case for `duration` seconds; returns (result dict as Tcl text, CSV path)."""
    out_dir.mkdir(parents=True, exist_ok=True)
    csv_path = out_dir / 'pound.csv'
    dabs.pset('::bridgeLibraryOnly', 1)
    dabs.pset('::bridgeFile', str(HERE / 'bridge.tcl'))
    dabs.tcl('source $::bridgeFile')
    dabs.pset('::duration', duration)
    dabs.pset('::poundCsv', str(csv_path))
    dabs.pset('::poundMotion', motion)
    dabs.tcl('set ::poundResult [runCase pound 1.0 $defaultDt $defaultIntegrator $defaultTol'
             ' $::poundMotion $::poundCsv]')
    return csv_path


def peak(name):
    return float(dabs.tcl('dict get [dict get $::poundResult peak] ' + name))


def read_gaps(csv_path):
    with open(csv_path, newline='') as f:
        rows = list(csv.DictReader(f))
    columns = [c for c in rows[0] if c.startswith('gap') and c[-1] in 'xy']
    return [float(r['t']) for r in rows], {c: [float(r[c]) for r in rows] for c in columns}


def plot(times, gaps, png, joint_gap):
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        print('no plot: matplotlib is not installed (Debian python3-matplotlib)')
        return None
    fig, ax = plt.subplots(figsize=(9, 4))
    for name, values in gaps.items():
        ax.plot(times, values, label=name, linewidth=0.8)
    ax.axhline(-joint_gap, color='k', linestyle='--', linewidth=0.6, label='-joint gap: the girder axes meet')
    ax.set_xlabel('time (s)')
    ax.set_ylabel('relative displacement of the girder ends (m)')
    ax.set_title('Pound case: joint gap histories (bridge.py)')
    ax.legend(loc='best', fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print('plot: %s' % png)
    return png


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--duration', type=float, default=20.0, help='seconds of motion (20)')
    parser.add_argument('--out', default='bridge-py-out', help='output folder (bridge-py-out)')
    parser.add_argument('--motion', default='auto', help='auto | record | pulse | file.AT2')
    args = parser.parse_args(argv)
    out_dir = pathlib.Path(args.out)
    csv_path = run_pound(args.duration, out_dir, args.motion)
    completed = dabs.tcl('dict get $::poundResult completed') == '1'
    print('pound case, %g s of %s: %s' % (args.duration, dabs.tcl('dict get $::poundResult motion'),
                                          'completed' if completed else 'FAILED'))
    for j in (1, 2):
        print('joint %d: peak gap x %.5f m, y %.5f m, peak pounding force %.1f kN'
              % (j, peak('gap%dx' % j), peak('gap%dy' % j), peak('force%d' % j)))
    times, gaps = read_gaps(csv_path)
    plot(times, gaps, out_dir / 'gaps.png', float(dabs.tcl('set ::jointGap')))
    return 0 if completed else 1


if __name__ == '__main__':
    sys.exit(main())
