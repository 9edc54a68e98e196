#!/usr/bin/env python3
# Copyright (c) 2026 the Graphcut_remeshing developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Drives `render_mesh`, which draws the pictures of the manual: well-formed SVG, triangles
coloured by their smallest angle, hidden faces left out, repeatable files of a sensible size,
histograms with their legends, and its refusals.

usage: test_render_mesh_cli.py RENDER_MESH DATA_DIR
"""
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

from cli_checks import check, finish

SVG = '{http://www.w3.org/2000/svg}'


def run(args):
    return subprocess.run([tool] + args, capture_output=True, text=True, timeout=300)


def off(points, faces):
    return 'OFF\n%d %d 0\n' % (len(points), len(faces)) + ''.join(
        '%r %r %r\n' % tuple(p) for p in points) + ''.join(
        '3 %d %d %d\n' % tuple(f) for f in faces)


def triangle_fills(path):
    """The fill colours of the triangles, in the order they are painted."""
    root = ET.parse(path).getroot()
    fills = []
    for g in root.iter(SVG + 'g'):
        for p in g.findall(SVG + 'path'):
            if re.fullmatch(r'M[-\d. ]+L[-\d. ]+L[-\d. ]+z', p.get('d', '')) and p.get('fill'):
                fills.append(p.get('fill'))
    return root, fills


def rgb(colour):
    return tuple(int(colour[i:i + 2], 16) for i in (1, 3, 5))


tool, data_dir = sys.argv[1], sys.argv[2]
fandisk = os.path.join(data_dir, 'fandisk.off')

with tempfile.TemporaryDirectory() as tmp:
    # A regular tetrahedron (all angles 60 degrees) and a flat sliver pair (tiny angles).
    tetra = os.path.join(tmp, 'tetra.off')
    with open(tetra, 'w') as f:
        f.write(off([(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)],
                    [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]))
    sliver = os.path.join(tmp, 'sliver.off')
    with open(sliver, 'w') as f:
        f.write(off([(0, 0, 0), (10, 0, 0), (5, 0.3, 0), (5, -0.3, 0)], [(0, 1, 2), (1, 0, 3)]))

    picture = os.path.join(tmp, 'tetra.svg')
    r = run(['--view', '1', '1', '1', tetra, picture])
    check(r.returncode == 0 and r.stdout == '' and r.stderr == '', "tetra: %d %r" % (r.returncode, r.stderr))
    root, fills = triangle_fills(picture)
    check(root.tag == SVG + 'svg', "not an SVG root: %s" % root.tag)
    # Seen from a vertex direction, a closed tetrahedron shows three faces: the hidden one is left out.
    check(len(fills) == 3, "tetra: %d triangles drawn, 3 expected" % len(fills))
    check(all(rgb(c)[1] > rgb(c)[0] for c in fills), "equilateral triangles not coloured as 60 degrees: %s" % fills)
    check(root.find('.//' + SVG + 'linearGradient') is not None, "no colour bar")

    # An open surface shows both sides; slivers are coloured as such (red over green).
    r = run(['--view', '0', '0', '-1', '--no-edges', sliver, os.path.join(tmp, 'sliver.svg')])
    root, fills = triangle_fills(os.path.join(tmp, 'sliver.svg'))
    check(r.returncode == 0 and len(fills) == 2, "sliver: %d, %d triangles" % (r.returncode, len(fills)))
    check(all(rgb(c)[0] > rgb(c)[1] for c in fills), "slivers not coloured as small angles: %s" % fills)

    # fandisk: every front triangle and no more, repeatable, well under the size budget.
    a, b = os.path.join(tmp, 'a.svg'), os.path.join(tmp, 'b.svg')
    r = run(['--size', '720', '--title', 'fandisk & <co>', fandisk, a])
    check(r.returncode == 0, "fandisk picture: %d %r" % (r.returncode, r.stderr))
    run(['--size', '720', '--title', 'fandisk & <co>', fandisk, b])
    with open(a, 'rb') as fa, open(b, 'rb') as fb:
        check(fa.read() == fb.read(), "the same picture twice differs")
    root, fills = triangle_fills(a)
    check(12946 * 0.3 < len(fills) < 12946 * 0.7, "fandisk: %d of 12946 triangles drawn" % len(fills))
    check(os.path.getsize(a) < 1500000, "fandisk picture of %d bytes" % os.path.getsize(a))
    check(root.get('width') == '720', "width %r" % root.get('width'))
    texts = ''.join(t.text or '' for t in root.iter(SVG + 'text'))
    check('fandisk & <co>' in texts and '12946 triangles' in texts and '43.46' in texts,
          "title or figures missing: %r" % texts[:200])

    # Histograms: one curve a mesh, the legend with labels and figures.
    h = os.path.join(tmp, 'h.svg')
    r = run(['--histogram', '--label', 'before', '--label', 'after', fandisk, tetra, h])
    check(r.returncode == 0, "histogram: %d %r" % (r.returncode, r.stderr))
    root = ET.parse(h).getroot()
    texts = ' '.join(''.join(t.itertext()) for t in root.iter(SVG + 'text'))
    check('before: 12946 triangles, mean 43.46' in texts and 'after: 4 triangles, mean 60.00' in texts,
          "histogram legend: %r" % texts)
    r = run(['--histogram', '--all-angles', '--bin', '5', fandisk, h])
    root = ET.parse(h).getroot()
    texts = ' '.join(''.join(t.itertext()) for t in root.iter(SVG + 'text'))
    check(r.returncode == 0 and 'equilateral' in texts and '38838 angles' in texts and '180' in texts,
          "all-angles histogram: %r" % texts[:300])

    r = run(['--help'])
    check(r.returncode == 0, "--help exit code")
    for option in ('--view', '--up', '--size', '--histogram', '--all-angles', '--bin', '--label', '--title',
                   '--no-edges'):
        check(option in r.stdout, "--help does not document %s" % option)

    # Refusals: exit code 1, one line, nothing written.
    never = os.path.join(tmp, 'never.svg')
    for args, expected in (([fandisk], 'usage'),
                           ([fandisk, os.path.join(tmp, 'mesh.off')], '.svg'),
                           ([os.path.join(tmp, 'missing.off'), never], 'cannot open'),
                           (['--view', '0', '0', '0', fandisk, never], 'non-zero'),
                           (['--size', 'big', fandisk, never], 'number'),
                           (['--frobnicate', fandisk, never], 'unknown option'),
                           ([fandisk, tetra, never], 'usage')):
        r = run(args)
        check(r.returncode == 1 and expected in r.stderr, "%s: %d %r" % (args, r.returncode, r.stderr))
        check(not os.path.exists(never) and not os.path.exists(os.path.join(tmp, 'mesh.off')),
              "%s: a file was written" % args)

finish("render_mesh CLI")
