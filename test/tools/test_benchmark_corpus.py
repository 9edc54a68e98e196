#!/usr/bin/env python3
# Copyright (c) 2026 the Graphcut_remeshing developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Drives `benchmark_remeshing --corpus` on a directory it writes: the meshes small enough get a
row each with both times and their ratio in the summary, the larger and the unreadable ones are
listed as left out with their reason, the JSON holds the same rows with the figures of the
smallest-angle bars, and the options of the other modes are refused.

usage: test_benchmark_corpus.py BENCHMARK_REMESHING
"""
import json
import os
import re
import subprocess
import sys
import tempfile

from cli_checks import check, finish


def run(args):
    return subprocess.run([tool] + args, capture_output=True, text=True, timeout=600)


def off(points, faces):
    return 'OFF\n%d %d 0\n' % (len(points), len(faces)) + ''.join(
        '%r %r %r\n' % tuple(p) for p in points) + ''.join(
        '%d %s\n' % (len(f), ' '.join(map(str, f))) for f in faces)


def octahedron(scale):
    points = [(scale, 0, 0), (-scale, 0, 0), (0, scale, 0), (0, -scale, 0), (0, 0, scale), (0, 0, -scale)]
    faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    return off(points, faces)


tool = sys.argv[1]
with tempfile.TemporaryDirectory() as tmp:
    data = os.path.join(tmp, 'data')
    os.mkdir(data)
    with open(os.path.join(data, 'tetra.off'), 'w') as f:
        f.write(off([(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)], [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]))
    with open(os.path.join(data, 'octahedron.off'), 'w') as f:
        f.write(octahedron(2.0))
    with open(os.path.join(data, 'cube.obj'), 'w') as f:  # 8 vertices: over the limit below
        f.write(''.join('v %d %d %d\n' % (x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)))
        f.write('f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n')
    with open(os.path.join(data, 'points.off'), 'w') as f:  # no face: refused
        f.write('OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n')
    with open(os.path.join(data, 'notes.txt'), 'w') as f:  # not a mesh format: not tried
        f.write('not a mesh\n')

    out_json = os.path.join(tmp, 'corpus.json')
    r = run(['--corpus', '--max-vertices', '6', '--data', data, '--json', out_json])
    check(r.returncode == 0, 'exit code %d: %s' % (r.returncode, r.stderr[-500:]))
    rows = [l.split()[0] for l in r.stdout.splitlines() if re.match(r'\S+\.(off|obj|ply|stl)\s+\d', l)]
    check(rows == ['octahedron.off', 'tetra.off'], 'rows %r' % rows)
    summary = re.search(r'time ratio, ours / CGAL, over (\d+) meshes: median ([\d.]+), 90th percentile ([\d.]+), '
                        r'largest ([\d.]+) \((\S+)\)', r.stdout)
    check(summary is not None and summary.group(1) == '2', 'summary line: %r' % r.stdout[-600:])
    if summary:
        median, p90, largest = (float(summary.group(i)) for i in (2, 3, 4))
        check(0 < median <= p90 <= largest, 'ratios %r' % (summary.groups(),))
        check(summary.group(5) in rows, 'the largest ratio names a row: %r' % summary.group(5))
    check('2 files left out' in r.stdout, 'left out count: %r' % r.stdout[-400:])
    check(re.search(r'cube\.obj: 8 vertices', r.stdout) is not None, 'cube.obj left out for its size')
    check(re.search(r'points\.off: .+', r.stdout) is not None, 'points.off left out with a reason')
    check('notes.txt' not in r.stdout, 'a .txt file is not tried')
    with open(out_json) as f:
        meshes = json.load(f)['meshes']
    check(sorted(m['name'] for m in meshes) == rows, 'JSON rows %r' % [m['name'] for m in meshes])
    check(all(m['ours']['seconds'] > 0 and m['cgal']['seconds'] >= 0 for m in meshes), 'JSON times')
    # What the smallest-angle bars need: the input's smallest angle and its sharp and border edges
    # (both regular solids: every angle 60 degrees, every edge of a dihedral angle far above 35),
    # each result's smallest angle and share of triangles below 30 degrees.
    edges = {'tetra.off': 6, 'octahedron.off': 12}
    for m in meshes:
        check(abs(m['input_min_angle'] - 60) < 1e-6, '%s: input_min_angle %r' % (m['name'], m['input_min_angle']))
        check(m['input_sharp_edges'] == edges[m['name']] and m['input_border_edges'] == 0,
              '%s: sharp %r, border %r' % (m['name'], m['input_sharp_edges'], m['input_border_edges']))
        for method in ('ours', 'cgal'):
            q = m[method]
            check(0 < q['min_angle'] <= 60 + 1e-6 and 0 <= q['poor_percent'] <= 100,
                  '%s %s: min_angle %r, poor_percent %r' % (m['name'], method, q['min_angle'], q['poor_percent']))

    for wrong in (['--corpus', '--quality'], ['--corpus', '--meshes', 'fandisk'], ['--corpus', '--seeds', '0'],
                  ['--max-vertices', '10', '--skip-large'], ['--corpus', '--max-vertices', '0']):
        r = run(wrong + ['--data', data])
        check(r.returncode == 1 and r.stderr.strip() != '', '%r: exit %d, %r' % (wrong, r.returncode, r.stderr))
finish('benchmark_remeshing --corpus')
