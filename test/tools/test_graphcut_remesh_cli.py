#!/usr/bin/env python3
# Copyright (c) 2026 the Graphcut_remeshing developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Drives `graphcut_remesh` as a user would: its JSON report, its repeatability, its options, its
help, its refusals, its file formats and its progress bar on a terminal.

usage: test_graphcut_remesh_cli.py GRAPHCUT_REMESH DATA_DIR [--sanitized]
"""
import json
import os
import subprocess
import sys
import tempfile
import threading

from cli_checks import check, finish


def run(args):
    return subprocess.run([tool] + args, capture_output=True, text=True, timeout=600)


tool, data_dir = sys.argv[1], sys.argv[2]
sanitized = '--sanitized' in sys.argv[3:]  # the sanitizer build: slower, and more memory
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
    check(j.get('mode') == 're-sampling' and j.get('target_edge_length', 0) > 0,
          "the JSON's mode and target: %r %r" % (j.get('mode'), j.get('target_edge_length')))
    check('re-sampling' in r.stdout and 'target edge length' in r.stdout, "the table says no mode: %r" % r.stdout)
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
    # Re-sampled at the input's mean edge length: about isotropic_remeshing's count there (3568
    # for triceratops' 2832 vertices).
    check(0.9 * j['input']['vertices'] < j['output']['vertices'] < 1.45 * j['input']['vertices'],
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

    check(j.get('target_edge_length', 0) > 0, "the JSON lacks the input's mean edge length as the target")
    check(j.get('mode') == 'relocation only', "--no-connectivity: the JSON's mode is %r" % j.get('mode'))

    # --target-vertices: the count lands within 10 % of N (the tool aims at 5 %, in at most 4 runs)
    # and the JSON says what it aimed at; the number of threads changes nothing in the output.
    r = run([mesh, out2, '--quiet', '--target-vertices', '1400', '--threads', '1', '--json', report] + short)
    with open(report) as f:
        j = json.load(f)
    check(r.returncode == 0 and abs(j['output']['vertices'] - 1400) <= 140,
          "--target-vertices 1400: %d, %d vertices" % (r.returncode, j['output']['vertices']))
    check(j.get('target_vertices') == 1400 and 1 <= j.get('runs', 0) <= 4 and j.get('target_edge_length', 0) > 0,
          "--target-vertices JSON: %r" % {k: j.get(k) for k in ('target_vertices', 'runs', 'target_edge_length')})
    os.remove(out3)
    r = run([mesh, out3, '--quiet', '--target-vertices', '1400', '--threads', '2'] + short)
    check(r.returncode == 0, "--threads 2: exit code %d (%s)" % (r.returncode, r.stderr))
    with open(out2, 'rb') as a, open(out3, 'rb') as b:
        check(a.read() == b.read(), "--threads 1 and 2 gave different outputs")

    # --distance-bound-ratio: the output keeps within R times the diagonal, by the call's measure and by
    # the tool's, and both say so; so does --distance-bound, in the input's units.
    joint = os.path.join(data_dir, 'joint.off')
    # Under the sanitizer the bounded connectivity passes take minutes: the relocation alone there.
    bounded = ['--iterations', '3', '--greedy-iterations', '1', '--no-connectivity'] if sanitized else short
    r = run([joint, out2, '--distance-bound-ratio', '2e-3', '--json', report] + bounded)
    with open(report) as f:
        j = json.load(f)
    check(r.returncode == 0 and 'distance bound' in r.stdout and 'distance achieved' in r.stdout,
          "--distance-bound-ratio: %d %r" % (r.returncode, r.stdout))
    check(0 < j.get('distance_achieved', 1) <= j.get('distance_bound', 0),
          "--distance-bound-ratio JSON: %r" % {k: j.get(k) for k in ('distance_bound', 'distance_achieved')})
    check(j['distance']['hausdorff'] <= 2e-3, "the tool measures %r against a bound of 2e-3" % j['distance'])
    bound = round(j['distance_bound'], 3)
    r = run([joint, out3, '--quiet', '--distance-bound', str(bound), '--json', report] + bounded)
    with open(report) as f:
        j = json.load(f)
    check(r.returncode == 0 and j.get('distance_bound') == bound and 0 < j.get('distance_achieved', 1) <= bound,
          "--distance-bound %r: %r" % (bound, {k: j.get(k) for k in ('distance_bound', 'distance_achieved')}))

    r = run(['--help'])
    check(r.returncode == 0 and r.stderr == '', "--help exit code %d, stderr %r" % (r.returncode, r.stderr))
    for option in ('--seed', '--json', '--iterations', '--greedy-iterations', '--lambda-data',
                   '--face-data-weight', '--no-connectivity', '--no-resampling', '--sharp-angle', '--quiet', '--help',
                   '--target-length', '--target-vertices', '--sizing-tolerance', '--threads', '--distance-bound',
                   '--distance-bound-ratio'):
        check(option in r.stdout, "--help does not document %s" % option)
    for fmt in ('OFF', 'OBJ', 'PLY', 'STL'):
        check(fmt in r.stdout, "--help does not name the %s format" % fmt)
    # Every option with its default: an option's text runs from its line to the next option's.
    help_options = {}
    for line in r.stdout.splitlines():
        if line.startswith('  --'):
            name = line.split()[0]
            help_options[name] = line
        elif help_options and line.startswith('    '):
            help_options[name] += ' ' + line.strip()
    check(len(help_options) >= 9, "--help lists %d options" % len(help_options))
    for name, text in help_options.items():
        check('default' in text, "--help gives no default for %s: %r" % (name, text))
    for name, default in (('--seed', 'default 0'), ('--iterations', 'default 75; with --no-resampling, --target-length or --target-vertices, the paper\'s 150'),
                          ('--greedy-iterations', 'default 10; with --no-resampling, --target-length or --target-vertices 20'), ('--json', 'default: no JSON'),
                          ('--sharp-angle', 'default 20 50; with --no-resampling, --target-length or --target-vertices, the paper\'s 20 35'),
                          ('--no-resampling', 'default: re-sampling')):
        check(default in help_options.get(name, ''), "--help: %s should say %r" % (name, default))

    # Refusals: exit code 1, no output file.
    missing_out = os.path.join(tmp, 'never.off')
    r = run([mesh])
    check(r.returncode == 1 and 'expected INPUT and OUTPUT' in r.stderr and
          'usage: graphcut_remesh INPUT OUTPUT' in r.stderr and r.stdout == '',
          "missing OUTPUT: %d %r %r" % (r.returncode, r.stdout, r.stderr))
    r = run([mesh, '--quiet'] + short)
    check(r.returncode == 1 and 'usage: graphcut_remesh INPUT OUTPUT' in r.stderr,
          "missing OUTPUT after options: %d %r" % (r.returncode, r.stderr))
    r = run([])
    check(r.returncode == 1 and 'usage: graphcut_remesh' in r.stderr, "no arguments: %d" % r.returncode)
    # Hysteresis bounds in the wrong order are refused.
    r = run([mesh, missing_out, '--sharp-angle', '40', '30'] + short)
    check(r.returncode == 1 and 'LOW <= HIGH' in r.stderr and not os.path.exists(missing_out),
          "--sharp-angle 40 30: %d %r" % (r.returncode, r.stderr))
    # A length and a count together, or no thread, are refused.
    r = run([mesh, missing_out, '--target-length', '0.5', '--target-vertices', '900'] + short)
    check(r.returncode == 1 and 'not both' in r.stderr and not os.path.exists(missing_out),
          "--target-length with --target-vertices: %d %r" % (r.returncode, r.stderr))
    for bad in (['--distance-bound', '0'], ['--distance-bound-ratio', '-1'],
                ['--distance-bound', '0.1', '--distance-bound-ratio', '0.001']):
        r = run([mesh, missing_out] + bad + short)
        check(r.returncode == 1 and not os.path.exists(missing_out), "%s: %d %r" % (bad, r.returncode, r.stderr))
    r = run([mesh, missing_out, '--threads', '0'] + short)
    check(r.returncode == 1 and not os.path.exists(missing_out), "--threads 0: %d %r" % (r.returncode, r.stderr))
    # An output format that cannot be written is refused before the work, with one line.
    unwritable = os.path.join(tmp, 'never.xyz')
    r = run([mesh, unwritable] + short)
    check(r.returncode == 1 and len(r.stderr.strip().splitlines()) == 1 and 'OFF, OBJ, PLY or STL' in r.stderr
          and r.stdout == '', "unwritable format: %d %r" % (r.returncode, r.stderr))
    check(not os.path.exists(unwritable), "an output was written in an unknown format")
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
        'only a face with a repeated point': (off(tetra_points, [(0, 2, 2)]), 'no faces with three distinct points'),
        'only degenerate faces': (off([(0, 0, 0), (1, 0, 0), (2, 0, 0), (3, 0, 0)], tetra_faces), 'degenerate'),
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

    # Repairs are made as CGAL's read_polygon_mesh makes them, and said: quads triangulated, unused
    # points dropped, repeated points merged, non-manifold vertices and edges split, degenerate
    # faces removed where that keeps the topology, faces reoriented.
    cube_points = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    cube_quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    # The tetrahedron with its point 3 repeated: each face that uses it has its own copy.
    split_points = tetra_points + [(0, 0, 1), (0, 0, 1)]
    split_faces = [(0, 2, 1), (0, 1, 3), (1, 2, 4), (0, 5, 2)]
    repairs = (
        ('quads', off(cube_points, cube_quads), ['6 faces with more than three sides']),
        ('unused point', off(tetra_points + [(5, 5, 5)], tetra_faces), ['1 vertices on no face']),
        ('repeated points', off(split_points, split_faces), ['2 repeated points merged']),
        ('non-manifold vertex', off([(0, 0, 0), (1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0)], [(0, 1, 2), (0, 3, 4)]),
         ['1 vertices added to split non-manifold']),
        ('non-manifold edge', off(tetra_points + [(1, 1, 1)], [(0, 1, 2), (1, 0, 3), (0, 1, 4)]),
         ['vertices added to split non-manifold']),
        ('inconsistent orientation', off(tetra_points, tetra_faces[:3] + [(0, 2, 3)]), ['faces reoriented consistently']),
        ('degenerate face', off([(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0)], [(0, 1, 3), (1, 2, 3), (0, 2, 1)]),
         ['1 degenerate faces repaired by edge flips (remove_almost_degenerate_faces), the topology kept']),
    )
    for name, text, expected in repairs:
        path = os.path.join(tmp, 'repaired.off')
        with open(path, 'w') as f:
            f.write(text)
        r = run([path, out3] + short)
        check(r.returncode == 0 and all(e in r.stderr for e in expected),
              "%s: exit %d, stderr %r" % (name, r.returncode, r.stderr))
        check(os.path.exists(out3), "%s: no output" % name)
        os.remove(out3) if os.path.exists(out3) else None

    # Counts a file declares that it cannot hold: refused in one line, at once, in little memory,
    # before CGAL's readers size their arrays by them.
    header = ('ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\n'
              'property float z\nelement face %d\nproperty list %s int vertex_indices\nend_header\n')
    triangle_points = '0 0 0\n1 0 0\n0 1 0\n'
    stl_header = b'\0' * 80
    stl_triangle = b''.join(int(v).to_bytes(4, 'little') for v in (0,) * 12) + b'\0\0'
    hostile = {
        'face.off': 'OFF\n3 1 0\n' + triangle_points + '1000000000 0 1 2\n',
        'faces.off': 'OFF\n3 1000000000 0\n' + triangle_points + '3 0 1 2\n',
        'points.off': 'OFF\n1000000000 1 0\n' + triangle_points + '3 0 1 2\n',
        'list.ply': header % (3, 1, 'int') + triangle_points + '1000000000 0 1 2\n',
        'faces.ply': header % (3, 1000000000, 'uchar') + triangle_points + '3 0 1 2\n',
        'points.ply': header % (1000000000, 1, 'uchar') + triangle_points + '3 0 1 2\n',
        'index.obj': 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1000000000\n',
        'negative.obj': 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -1000000000\n',
        'count.stl': stl_header + (1000000000).to_bytes(4, 'little') + stl_triangle,
    }
    seconds, megabytes = (10, 400) if sanitized else (1, 100)
    for name, content in hostile.items():
        path = os.path.join(tmp, name)
        with open(path, 'wb') as f:
            f.write(content if isinstance(content, bytes) else content.encode())
        # Timed in a child of its own, so that its peak memory is its own; outside the sanitizer
        # build, its address space is bounded too, so that a reader that believes the count fails
        # instead of taking the machine (and is caught by the missing 'declares').
        probe = ('import resource, subprocess, sys, time\n'
                 'limit = (lambda: resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))) if sys.argv[1] == "1" else None\n'
                 't = time.time()\n'
                 'try:\n'
                 '    r = subprocess.run(sys.argv[2:], capture_output=True, text=True, timeout=20, preexec_fn=limit)\n'
                 '    code, err = r.returncode, r.stderr\n'
                 'except subprocess.TimeoutExpired:\n'
                 '    code, err = "timeout", ""\n'
                 'print(code, time.time() - t, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n'
                 'sys.stderr.write(err)\n')
        p = subprocess.run([sys.executable, '-c', probe, '0' if sanitized else '1', tool, path, missing_out],
                           capture_output=True, text=True, timeout=120)
        code, wall, kilobytes = p.stdout.split()
        lines = p.stderr.strip().splitlines()
        check(code == '1' and len(lines) == 1 and not os.path.exists(missing_out),
              "%s: exit %s, stderr %r" % (name, code, p.stderr))
        check(float(wall) < seconds and int(kilobytes) < megabytes * 1024,
              "%s: refused in %.2f s and %d KB (bounds %d s, %d MB)" % (name, float(wall), int(kilobytes),
                                                                       seconds, megabytes))
        if not name.endswith('.obj'):
            check('declares' in p.stderr, "%s: the refusal does not say what the file declares: %r" % (name, p.stderr))

    # Formats: a chain of remeshings through OBJ, PLY, STL and back to OFF. Each file is written in
    # its format, read back as the next input, and holds the mesh written (the JSON figures of one
    # step's output are those of the next step's input).
    tiny = ['--iterations', '2', '--greedy-iterations', '1']
    chain = [mesh] + [os.path.join(tmp, 'chain.' + ext) for ext in ('obj', 'ply', 'stl', 'off', 'OBJ')]
    previous = None
    for source, target in zip(chain, chain[1:]):
        ext = os.path.splitext(target)[1].lower()
        r = run([source, target, '--quiet', '--json', report] + tiny)
        check(r.returncode == 0 and os.path.exists(target), "%s -> %s: exit %d %r" % (
            os.path.basename(source), os.path.basename(target), r.returncode, r.stderr))
        if r.returncode != 0 or not os.path.exists(target):
            break
        with open(target, 'rb') as f:
            head = f.read(200)
        if ext == '.obj':
            check(b'\nv ' in head or head.startswith(b'v '), "%s is not OBJ: %r" % (target, head[:60]))
        elif ext == '.ply':
            check(head.startswith(b'ply\n') and b'binary_little_endian' in head and b'property double x' in head,
                  "%s is not a binary PLY of doubles: %r" % (target, head[:80]))
        elif ext == '.stl':
            # Binary STL: an 80-byte header, the triangle count, 50 bytes a triangle.
            size = os.path.getsize(target)
            count = int.from_bytes(head[80:84], 'little')
            check(size == 84 + 50 * count, "%s is not a binary STL (%d bytes, %d triangles)" % (target, size, count))
        elif ext == '.off':
            check(head.startswith(b'OFF'), "%s is not OFF: %r" % (target, head[:20]))
        with open(report) as f:
            j = json.load(f)
        if previous is not None:
            check(j['input']['vertices'] == previous['vertices'] and j['input']['faces'] == previous['faces'],
                  "%s read back with %d/%d vertices/faces, written with %d/%d" % (
                      os.path.basename(source), j['input']['vertices'], j['input']['faces'],
                      previous['vertices'], previous['faces']))
            # Doubles survive OFF, OBJ and PLY; STL holds floats.
            tolerance = 1e-3 if source.endswith('.stl') else 1e-6
            for key in ('mean_min_angle', 'mean_max_angle'):
                check(abs(j['input'][key] - previous[key]) < tolerance, "%s: %s %r, written %r" % (
                    os.path.basename(source), key, j['input'][key], previous[key]))
        previous = j['output']

    # The progress bar: on stderr when it is a terminal, never in a pipe or with --quiet.
    r = run([mesh, out2] + short)
    check(r.returncode == 0 and '\r' not in r.stderr and r.stderr == '', "piped stderr got %r" % r.stderr[:200])
    try:
        import pty
    except ImportError:
        pty = None
    if pty is not None:
        def run_on_terminal(args):
            master, slave = pty.openpty()
            received = []

            def drain():
                while True:
                    try:
                        data = os.read(master, 4096)
                    except OSError:
                        return
                    if not data:
                        return
                    received.append(data)
            reader = threading.Thread(target=drain)
            reader.start()
            p = subprocess.run([tool] + args, stdout=subprocess.PIPE, stderr=slave, timeout=600)
            os.close(slave)
            reader.join(10)
            os.close(master)
            return p.returncode, b''.join(received).decode(errors='replace')
        code, err = run_on_terminal([mesh, out2] + short)
        check(code == 0 and '\r' in err and 'relocation' in err and 'greedy fitting' in err and
              '15/15' in err and 'energy' in err and 'ETA' in err, "no progress bar on a terminal: %r" % err[:300])
        check(err.endswith('\r\x1b[K'), "the progress bar does not clear its line: %r" % err[-40:])
        code, err = run_on_terminal([mesh, out2, '--quiet'] + short)
        check(code == 0 and err == '', "--quiet on a terminal printed %r" % err[:200])

finish("graphcut_remesh CLI")
