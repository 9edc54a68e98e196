# Copyright (c) 2026 the Graphcut_remeshing developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Every mesh of CGAL's sample data (data/meshes of Debian's libcgal-demo) up to a size, as a new
user would try it: graphcut_remesh with a short schedule, then `mesh_quality --check`, which
checks the output against CGAL's reading of the input (a valid triangle mesh without degenerate
faces, the same Euler characteristic, components and border cycles, no intersecting pair of
triangles away from the input's own, the corners at their exact coordinates). A file the tool refuses must be refused in one
line on stderr, with exit code 1 and no output file. Prints a line a file, then the summary.

usage: test_sample_corpus.py GRAPHCUT_REMESH MESH_QUALITY DATA_DIR [--max-vertices N] [--defaults]

--max-vertices 0 tries every file; --defaults remeshes with the tool's defaults instead of the
short schedule (the whole corpus with defaults takes a few minutes).
"""
import os
import re
import subprocess
import sys
import tempfile
import time

SCHEDULE = ['--iterations', '10', '--greedy-iterations', '5']
QUIET = ['--quiet']  # no table: its distances are the slowest part of a short run


def declared_vertices(path):
    """The vertex count the file declares (OFF, PLY), or counts (OBJ), or bounds (STL: three a
    triangle, before repeated points are merged); None when it cannot tell."""
    ext = os.path.splitext(path)[1].lower()
    with open(path, 'rb') as f:
        data = f.read()
    if ext == '.off':
        words = re.sub(rb'#[^\n]*', b' ', data[:4096]).split()
        if not words or not words[0].endswith(b'OFF') or b'BINARY' in words[:2]:
            return None
        first = 2 if b'n' in words[0][:-3] else 1
        return int(words[first]) if len(words) > first and words[first].isdigit() else None
    if ext == '.ply':
        m = re.search(rb'element vertex (\d+)', data[:4096])
        return int(m.group(1)) if m else None
    if ext == '.obj':
        return len(re.findall(rb'(?m)^v\s', data))
    if ext == '.stl':
        if data.startswith(b'solid') and data[5:6].isspace():
            return 3 * data.count(b'facet normal') // 6  # a closed surface has half as many vertices as triangles
        return 3 * int.from_bytes(data[80:84], 'little') // 6 if len(data) >= 84 else None
    return None


def main():
    args = sys.argv[1:]
    max_vertices = 20000
    if '--max-vertices' in args:
        i = args.index('--max-vertices')
        max_vertices = int(args[i + 1])
        del args[i:i + 2]
    schedule = SCHEDULE
    if '--defaults' in args:
        args.remove('--defaults')
        schedule = []
    remesh, quality, data_dir = args
    files = sorted(f for f in os.listdir(data_dir) if os.path.splitext(f)[1].lower() in ('.off', '.obj', '.ply', '.stl'))
    passed, failed, refused, skipped = [], [], [], []
    times = []
    start = time.time()
    with tempfile.TemporaryDirectory() as tmp:
        for name in files:
            path = os.path.join(data_dir, name)
            n = declared_vertices(path)
            if max_vertices > 0 and n is not None and n > max_vertices:
                skipped.append(name)
                continue
            out = os.path.join(tmp, 'out.off')
            if os.path.exists(out):
                os.remove(out)
            t = time.time()
            r = subprocess.run([remesh, path, out] + schedule + QUIET, capture_output=True, text=True, timeout=600)
            seconds = time.time() - t
            times.append((seconds, name))
            if r.returncode == 1:
                lines = r.stderr.strip().splitlines()
                if len(lines) == 1 and not os.path.exists(out) and r.stdout == '':
                    refused.append(name)
                    print('%-32s refused: %s' % (name, lines[0]))
                else:
                    failed.append(name)
                    print('%-32s FAILED: a refusal must be one line, without output: %r' % (name, r.stderr[-500:]))
                continue
            if r.returncode != 0 or not os.path.exists(out):
                failed.append(name)
                print('%-32s FAILED: exit code %d: %r' % (name, r.returncode, r.stderr[-500:]))
                continue
            c = subprocess.run([quality, '--check', path, out], capture_output=True, text=True, timeout=600)
            if c.returncode == 0:
                passed.append(name)
                print('%-32s passed (%.1f s)' % (name, seconds))
            else:
                failed.append(name)
                print('%-32s FAILED: %s' % (name, (c.stdout + c.stderr).strip().replace('\n', '; ')))
    print('%d passed, %d failed (%d refused, %d larger than %d vertices not tried; %.0f s)' % (
        len(passed), len(failed), len(refused), len(skipped), max_vertices, time.time() - start))
    print('slowest: ' + ', '.join('%s %.1f s' % (name, seconds) for seconds, name in sorted(times, reverse=True)[:5]))
    if failed:
        print('failed: ' + ', '.join(failed))
    sys.exit(1 if failed or not passed else 0)


if __name__ == '__main__':
    main()
