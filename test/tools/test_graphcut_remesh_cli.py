#!/usr/bin/env python3
# Copyright (c) 2026 the Graphcut_remeshing developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Drives `graphcut_remesh` as a user would: its JSON report, its repeatability, its options and
its refusals.

usage: test_graphcut_remesh_cli.py GRAPHCUT_REMESH DATA_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

failures = []
checks = 0


def check(condition, message):
    global checks
    checks += 1
    if not condition:
        failures.append(message)
        print("FAIL: " + message)


def run(args):
    return subprocess.run([tool] + args, capture_output=True, text=True, timeout=600)


tool, data_dir = sys.argv[1], sys.argv[2]
mesh = os.path.join(data_dir, 'triceratops.off')
quality_keys = sorted(['vertices', 'faces', 'irregular_percent', 'mean_min_angle', 'mean_max_angle',
                       'min_angle', 'max_angle'])

with tempfile.TemporaryDirectory() as tmp:
    out1, out2, out3 = (os.path.join(tmp, n) for n in ('a.off', 'b.off', 'c.off'))
    report = os.path.join(tmp, 'report.json')
    short = ['--iterations', '12', '--greedy-iterations', '3']

    r = run([mesh, out1, '--json', report, '--seed', '4'] + short)
    check(r.returncode == 0, "remesh: exit code %d (%s)" % (r.returncode, r.stderr))
    check('mean min angle' in r.stdout and 'time (s)' in r.stdout, "table: %r" % r.stdout)
    with open(report) as f:
        j = json.load(f)
    for key in ('input', 'output', 'distance', 'seconds', 'energy'):
        check(key in j, "JSON lacks %s" % key)
    check(sorted(j['input'].keys()) == quality_keys, "input keys %s" % sorted(j['input'].keys()))
    check(sorted(j['output'].keys()) == quality_keys, "output keys")
    check(sorted(j['distance'].keys()) == ['hausdorff', 'rms'], "distance keys")
    check(len(j['energy']) == 1 + 12 + 3, "energy list has %d entries" % len(j['energy']))
    # Connectivity passes after iterations 5 and 10 change the triangles; elsewhere U never rises.
    check(j.get('connectivity_passes') == [5, 10], "passes %r" % j.get('connectivity_passes'))
    check(all(b <= a * (1 + 1e-12) for i, (a, b) in enumerate(zip(j['energy'], j['energy'][1:]))
              if i + 1 not in j['connectivity_passes']), "energy rose")
    check(j['energy'][-1] < j['energy'][0], "energy did not fall")
    for key in ('flips', 'splits', 'collapses', 'vertex_splits'):
        check(isinstance(j.get(key), int) and j[key] >= 0, "JSON lacks the count of %s" % key)
    check(j['flips'] > 0 and j['splits'] + j['collapses'] + j['vertex_splits'] > 0,
          "no connectivity change: %r" % {k: j[k] for k in ('flips', 'splits', 'collapses', 'vertex_splits')})
    check(abs(j['output']['vertices'] - j['input']['vertices']) < 0.15 * j['input']['vertices'],
          "vertex count %d -> %d" % (j['input']['vertices'], j['output']['vertices']))
    check(j['output']['mean_min_angle'] > j['input']['mean_min_angle'], "angles did not improve")
    check(0 < j['distance']['hausdorff'] < 0.01, "hausdorff %r" % j['distance'])

    # Same input and seed: byte-identical output; another seed: another output.
    run([mesh, out2, '--seed', '4', '--quiet'] + short)
    run([mesh, out3, '--seed', '5', '--quiet'] + short)
    with open(out1, 'rb') as a, open(out2, 'rb') as b, open(out3, 'rb') as c:
        x, y, z = a.read(), b.read(), c.read()
    check(x == y, "same seed, different output")
    check(x != z, "different seed, same output")

    r = run([mesh, out2, '--quiet', '--no-connectivity', '--json', report] + short)
    check(r.returncode == 0 and r.stdout == '' and r.stderr == '', "--quiet printed %r %r" % (r.stdout, r.stderr))
    with open(report) as f:
        j = json.load(f)
    check(j['output']['vertices'] == j['input']['vertices'], "--no-connectivity changed the vertex count")
    check(j['connectivity_passes'] == [] and j['flips'] == 0, "--no-connectivity ran a pass")
    check(all(b <= a * (1 + 1e-12) for a, b in zip(j['energy'], j['energy'][1:])), "energy rose")

    r = run(['--help'])
    check(r.returncode == 0, "--help exit code")
    for option in ('--seed', '--json', '--iterations', '--greedy-iterations', '--lambda-data',
                   '--no-connectivity', '--quiet'):
        check(option in r.stdout, "--help does not document %s" % option)

    # Refusals: exit code 1, no output file.
    missing_out = os.path.join(tmp, 'never.off')
    r = run([mesh])
    check(r.returncode == 1 and 'usage' in r.stderr, "missing OUTPUT: %d %r" % (r.returncode, r.stderr))
    garbage = os.path.join(tmp, 'garbage.off')
    with open(garbage, 'w') as f:
        f.write('not a mesh\n')
    r = run([garbage, missing_out])
    check(r.returncode == 1 and len(r.stderr.strip().splitlines()) == 1, "bad input: %d %r" % (r.returncode, r.stderr))
    check(not os.path.exists(missing_out), "an output was written for a bad input")
    r = run([os.path.join(tmp, 'nothing.off'), missing_out])
    check(r.returncode == 1 and not os.path.exists(missing_out), "missing input")
    r = run([mesh, missing_out, '--iterations', 'many'])
    check(r.returncode == 1 and not os.path.exists(missing_out), "bad --iterations")

    # Defective inputs: one line naming the defect, exit code 1, no output file.
    def off(points, faces):
        return 'OFF\n%d %d 0\n' % (len(points), len(faces)) + ''.join(
            '%s %s %s\n' % p for p in points) + ''.join(
            '%d %s\n' % (len(f), ' '.join(str(i) for i in f)) for f in faces)
    tetra_points = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    tetra_faces = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
    defective = {
        'no faces': (off(tetra_points, []), 'no faces'),
        'NaN': (off([(0, 0, 0), ('nan', 0, 0), (0, 1, 0), (0, 0, 1)], tetra_faces), 'non-finite'),
        'infinite': (off([(0, 0, 0), (1, 0, 0), (0, 'inf', 0), (0, 0, 1)], tetra_faces), 'non-finite'),
        'index out of range': (off(tetra_points, tetra_faces[:3] + [(0, 3, 7)]), 'refers to vertex 7'),
        'non-manifold edge': (off(tetra_points + [(1, 1, 1)], [(0, 1, 2), (1, 0, 3), (0, 1, 4)]), 'non-manifold'),
        'non-manifold vertex': (off([(0, 0, 0), (1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0)],
                                    [(0, 1, 2), (0, 3, 4)]), 'non-manifold vertex'),
        'degenerate face': (off([(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0)], [(0, 1, 3), (1, 2, 3), (0, 2, 1)]),
                            'degenerate'),
        'repeated vertex': (off(tetra_points, [(0, 2, 2)]), 'repeats vertex'),
    }
    for name, (text, expected) in defective.items():
        path = os.path.join(tmp, 'defective.off')
        with open(path, 'w') as f:
            f.write(text)
        r = run([path, missing_out] + short)
        lines = r.stderr.strip().splitlines()
        check(r.returncode == 1 and len(lines) == 1 and expected in r.stderr,
              "%s: exit %d, stderr %r" % (name, r.returncode, r.stderr))
        check(not os.path.exists(missing_out), "%s: an output was written" % name)

    # Repairs that lose nothing are made and said: quads triangulated, unused points dropped.
    cube_points = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    cube_quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    for name, text, expected in (('quads', off(cube_points, cube_quads), '6 faces with more than three sides'),
                                 ('unused point', off(tetra_points + [(5, 5, 5)], tetra_faces), '1 vertices on no face')):
        path = os.path.join(tmp, 'repaired.off')
        with open(path, 'w') as f:
            f.write(text)
        r = run([path, out3] + short)
        check(r.returncode == 0 and expected in r.stderr, "%s: exit %d, stderr %r" % (name, r.returncode, r.stderr))
        check(os.path.exists(out3), "%s: no output" % name)
        os.remove(out3) if os.path.exists(out3) else None

print("graphcut_remesh CLI: %d checks, %d failed" % (checks, len(failures)))
sys.exit(1 if failures else 0)
