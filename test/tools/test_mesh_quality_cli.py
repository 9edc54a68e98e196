#!/usr/bin/env python3
# Copyright (c) 2026 the Graphcut_remeshing developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Drives `mesh_quality` as a user would: its JSON against an independent measurement written
here (own OFF reader, law-of-cosines angles, valences from an edge table), its distances on a
case with a known answer, and its refusals of bad input.

usage: test_mesh_quality_cli.py MESH_QUALITY DATA_DIR
"""
import json
import shutil
import math
import os
import subprocess
import sys
import tempfile

from cli_checks import check, finish


def read_off(path):
    with open(path) as f:
        tokens = []
        for line in f:
            line = line.split('#', 1)[0]
            tokens.extend(line.split())
    assert tokens[0] == 'OFF'
    nv, nf = int(tokens[1]), int(tokens[2])
    pos = 4
    points = []
    for _ in range(nv):
        points.append(tuple(float(t) for t in tokens[pos:pos + 3]))
        pos += 3
    faces = []
    for _ in range(nf):
        k = int(tokens[pos])
        faces.append(tuple(int(t) for t in tokens[pos + 1:pos + 1 + k]))
        pos += 1 + k
    return points, faces


def independent_quality(points, faces):
    def dist(a, b):
        return math.sqrt(sum((a[i] - b[i]) ** 2 for i in range(3)))

    mins, maxs = [], []
    for f in faces:
        a, b, c = (points[i] for i in f)
        la, lb, lc = dist(b, c), dist(c, a), dist(a, b)  # sides opposite a, b, c
        angles = []
        for opposite, s1, s2 in ((la, lb, lc), (lb, lc, la), (lc, la, lb)):
            cosine = (s1 * s1 + s2 * s2 - opposite * opposite) / (2 * s1 * s2)
            angles.append(math.degrees(math.acos(max(-1.0, min(1.0, cosine)))))
        mins.append(min(angles))
        maxs.append(max(angles))
    edge_faces = {}
    for f in faces:
        for i in range(3):
            e = tuple(sorted((f[i], f[(i + 1) % 3])))
            edge_faces[e] = edge_faces.get(e, 0) + 1
    valence = [0] * len(points)
    border = [False] * len(points)
    for (u, v), count in edge_faces.items():
        valence[u] += 1
        valence[v] += 1
        if count == 1:
            border[u] = border[v] = True
    irregular = sum(1 for i in range(len(points)) if valence[i] != (4 if border[i] else 6))
    return {
        'vertices': len(points), 'faces': len(faces),
        'irregular_percent': 100.0 * irregular / len(points),
        'mean_min_angle': sum(mins) / len(mins), 'mean_max_angle': sum(maxs) / len(maxs),
        'min_angle': min(mins), 'max_angle': max(maxs),
    }


def run(args):
    return subprocess.run([tool] + args, capture_output=True, text=True, timeout=240)


def write_off(path, points, faces, raw_points=None):
    with open(path, 'w') as f:
        f.write('OFF\n%d %d 0\n' % (len(raw_points or points), len(faces)))
        for p in (raw_points or points):
            f.write(' '.join(str(c) for c in p) + '\n')
        for face in faces:
            f.write('%d %s\n' % (len(face), ' '.join(str(i) for i in face)))


def expect_refusal(name, args):
    r = run(args)
    check(r.returncode == 1, "%s: exit code %d, expected 1" % (name, r.returncode))
    lines = r.stderr.strip().splitlines()
    check(len(lines) == 1, "%s: expected one line on stderr, got %r" % (name, r.stderr))
    check(r.stdout == '', "%s: expected nothing on stdout, got %r" % (name, r.stdout))


tool, data_dir = sys.argv[1], sys.argv[2]

# 1. One mesh: the JSON against the independent measurement.
keys = ['vertices', 'faces', 'irregular_percent', 'mean_min_angle', 'mean_max_angle',
        'min_angle', 'max_angle']
for name in ('fandisk', 'cow', 'triceratops'):
    path = os.path.join(data_dir, name + '.off')
    r = run(['--json', path])
    check(r.returncode == 0, "%s: exit code %d (%s)" % (name, r.returncode, r.stderr))
    ours = json.loads(r.stdout)
    check(sorted(ours.keys()) == sorted(keys), "%s: keys %s" % (name, sorted(ours.keys())))
    ref = independent_quality(*read_off(path))
    check(ours['vertices'] == ref['vertices'] and ours['faces'] == ref['faces'],
          "%s: counts %s vs %s" % (name, (ours['vertices'], ours['faces']), (ref['vertices'], ref['faces'])))
    check(abs(ours['irregular_percent'] - ref['irregular_percent']) <= 0.05,
          "%s: irregular %.4f vs %.4f" % (name, ours['irregular_percent'], ref['irregular_percent']))
    for k in ('mean_min_angle', 'mean_max_angle', 'min_angle', 'max_angle'):
        check(abs(ours[k] - ref[k]) <= 0.05, "%s: %s %.4f vs %.4f" % (name, k, ours[k], ref[k]))
    print("%s: ours %s\n%s: independent %s" % (name, ours, name, ref))

# fandisk's published figures.
fandisk = os.path.join(data_dir, 'fandisk.off')
q = json.loads(run(['--json', fandisk]).stdout)
check(q['vertices'] == 6475, "fandisk vertices %d" % q['vertices'])
check(abs(q['irregular_percent'] - 19.83) < 0.005, "fandisk irregular %f" % q['irregular_percent'])
check(abs(q['mean_min_angle'] - 43.46) < 0.005, "fandisk mean min %f" % q['mean_min_angle'])
check(abs(q['mean_max_angle'] - 85.98) < 0.005, "fandisk mean max %f" % q['mean_max_angle'])

# The table is the default.
r = run([fandisk])
check(r.returncode == 0 and 'mean min angle' in r.stdout and '6475' in r.stdout, "table: %r" % r.stdout)

with tempfile.TemporaryDirectory() as tmp:
    # 2. Two meshes: a 2 x 2 square and its copy moved by 1 along z are at distance 1 everywhere.
    n = 5
    pts = [(2.0 * i / (n - 1), 2.0 * j / (n - 1), 0.0) for j in range(n) for i in range(n)]
    tris = []
    for j in range(n - 1):
        for i in range(n - 1):
            a, b, c, d = j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i
            tris += [(a, b, c), (a, c, d)]
    square, moved = os.path.join(tmp, 'square.off'), os.path.join(tmp, 'moved.off')
    write_off(square, pts, tris)
    write_off(moved, [(x, y, z + 1.0) for (x, y, z) in pts], tris)
    r = run(['--json', '--samples', '20000', square, moved])
    check(r.returncode == 0, "two meshes: exit code %d (%s)" % (r.returncode, r.stderr))
    both = json.loads(r.stdout)
    check(sorted(both.keys()) == ['distance', 'original', 'remeshed', 'sharp_lines'], "two meshes: keys %s" % both.keys())
    check(both['sharp_lines'] is None, "a flat square has no sharp line to measure (null): %r" % both['sharp_lines'])
    check(sorted(both['distance'].keys()) == ['hausdorff', 'rms'], "distance keys %s" % both['distance'].keys())
    expected = 1.0 / math.sqrt(8.0)
    check(abs(both['distance']['hausdorff'] - expected) < 1e-8, "hausdorff %r" % both['distance'])
    check(abs(both['distance']['rms'] - expected) < 1e-8, "rms %r" % both['distance'])
    check(sorted(both['original'].keys()) == sorted(keys), "original keys")
    r = run(['--json', '--samples', '20000', fandisk, fandisk])
    d = json.loads(r.stdout)['distance']
    check(d['hausdorff'] < 1e-12 and d['rms'] < 1e-12, "fandisk to itself: %r" % d)
    check(json.loads(r.stdout)['sharp_lines'] < 1e-12, "fandisk's sharp lines to themselves")
    # A sheet folded at a right angle along x = 1 (z = |x - 1|) and its copy moved by 1 along z:
    # the crease moved by 1, the diagonal is 3; on a flat copy there is no crease left (null).
    roof, roof_moved = os.path.join(tmp, 'roof.off'), os.path.join(tmp, 'roof_moved.off')
    write_off(roof, [(x, y, abs(x - 1.0)) for (x, y, z) in pts], tris)
    write_off(roof_moved, [(x, y, abs(x - 1.0) + 1.0) for (x, y, z) in pts], tris)
    s = json.loads(run(['--json', '--samples', '1000', roof, roof_moved]).stdout)['sharp_lines']
    check(abs(s - 1.0 / 3.0) < 1e-9, "moved crease: %r" % s)
    s = json.loads(run(['--json', '--samples', '1000', roof, square]).stdout)['sharp_lines']
    check(s is None, "crease to a flat square: %r" % s)
    # Same seed, same figures; the table shows the distances too.
    r1 = run(['--json', '--samples', '5000', '--seed', '3', square, moved]).stdout
    r2 = run(['--json', '--samples', '5000', '--seed', '3', square, moved]).stdout
    check(r1 == r2, "same seed gave different output")
    r = run([square, moved])
    check('Hausdorff' in r.stdout and 'RMS' in r.stdout and 'sharp lines' in r.stdout, "two-mesh table: %r" % r.stdout)
    sharp_row = [line for line in r.stdout.splitlines() if line.startswith('sharp lines')]
    check(len(sharp_row) == 1 and sharp_row[0].split()[-1] == 'n/a', "no sharp line: the table shows %r" % sharp_row)
    # A title longer than its column keeps its end, marked as cut.
    long_name = os.path.join(tmp, 'knot_resampled.off')
    shutil.copy(square, long_name)
    r = run([square, long_name])
    check('...esampled.off' in r.stdout.splitlines()[0], "a long title: %r" % r.stdout.splitlines()[0])

    # 3. Refusals: one line on stderr, exit code 1.
    expect_refusal('missing file', [os.path.join(tmp, 'nothing.off')])
    garbage = os.path.join(tmp, 'garbage.off')
    with open(garbage, 'w') as f:
        f.write('this is not a mesh\n')
    expect_refusal('not a mesh', [garbage])
    quads = os.path.join(tmp, 'quad.off')
    write_off(quads, [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [(0, 1, 2, 3)])
    expect_refusal('not triangles', [quads])
    nan = os.path.join(tmp, 'nan.off')
    write_off(nan, None, [(0, 1, 2)], raw_points=[(0, 0, 0), ('nan', 0, 0), (0, 1, 0)])
    expect_refusal('NaN coordinate', [nan])
    inf = os.path.join(tmp, 'inf.off')
    write_off(inf, None, [(0, 1, 2)], raw_points=[(0, 0, 0), (1, 0, 0), (0, 'inf', 0)])
    expect_refusal('infinite coordinate', [inf])
    out_of_range = os.path.join(tmp, 'range.off')
    write_off(out_of_range, [(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 7)])
    expect_refusal('index out of range', [out_of_range])
    empty = os.path.join(tmp, 'empty.off')
    write_off(empty, [(0, 0, 0)], [])
    expect_refusal('no faces', [empty])
    expect_refusal('bad remeshed file', [fandisk, garbage])
    expect_refusal('no argument', [])
    expect_refusal('unknown option', ['--frobnicate', fandisk])
    expect_refusal('bad sample count', ['--samples', 'many', fandisk])

    # 4. --check: a mesh keeps its own promises; a moved corner, a hole and a flattened
    # triangle are each named.
    r = run(['--check', fandisk, fandisk])
    check(r.returncode == 0 and r.stdout.strip() == 'ok', "--check of fandisk against itself: %d %r %r" % (
        r.returncode, r.stdout, r.stderr))
    tetra_points = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    tetra_faces = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
    tetra = os.path.join(tmp, 'tetra.off')
    write_off(tetra, tetra_points, tetra_faces)
    broken = {
        'moved corner': ([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1.5)], tetra_faces, 'corners moved'),
        'hole': (tetra_points, tetra_faces[:3], 'topology changed'),
        'flat triangle': ([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0.5, 0.5, 0)], tetra_faces, 'not a valid remesh'),
    }
    for name, (points, faces, expected) in broken.items():
        path = os.path.join(tmp, 'broken.off')
        write_off(path, points, faces)
        r = run(['--check', tetra, path])
        check(r.returncode == 1 and expected in r.stdout, "--check, %s: %d %r %r" % (name, r.returncode, r.stdout,
                                                                                   r.stderr))
    expect_refusal('--check with one mesh', ['--check', tetra])

    r = run(['--help'])
    check(r.returncode == 0 and 'usage' in r.stdout and '--check' in r.stdout, "--help")

finish("mesh_quality CLI")
