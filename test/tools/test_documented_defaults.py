#!/usr/bin/env python3
# Copyright (c) 2026 the Graphcut_remeshing developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The defaults of graphcut_isotropic_remeshing() are written once, in Remeshing_options and
Energy_weights; the reference manual, the user manual and graphcut_remesh --help repeat them for
their readers. This test reads all four and fails where one says another value.

usage: test_documented_defaults.py SOURCE_DIR GRAPHCUT_REMESH"""

import re
import subprocess
import sys

source, tool = sys.argv[1], sys.argv[2]
internal = source + '/include/CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/'
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def numbers(text):
    text = text.replace('true', '1').replace('false', '0')
    return [float(x) for x in re.findall(r'[-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?', text)]


def struct_defaults(path, name):
    body = re.search(r'struct %s\s*\{(.*?)\n\};' % name, open(path).read(), re.S).group(1)
    found = {}
    for m in re.finditer(r'^\s*[\w:<>, ]+?\s(\w+)\s*(?:=\s*([^;]+?)|\{([^}]*)\})\s*;', body, re.M):
        found[m.group(1)] = numbers(m.group(2) or m.group(3))
    return found


code = struct_defaults(internal + 'remeshing_options.h', 'Remeshing_options')
code.update(struct_defaults(internal + 'energy.h', 'Energy_weights'))
# CGAL's operation switches, by their named parameters.
operations = struct_defaults(internal + 'remeshing_options.h', 'Connectivity_operations')
for field, parameter in (('split', 'do_split'), ('collapse', 'do_collapse'), ('flip', 'do_flip'),
                         ('relaxation_steps', 'number_of_relaxation_steps')):
    code[parameter] = operations[field]
# The sharp-angle bounds are documented with both modes' defaults, re-sampling's first.
code['sharp_angle_bounds'] = code['sharp_angle_bounds'] + code.pop('paper_sharp_angle_bounds')
# So are the iteration counts.
paper_iterations = code.pop('paper_iterations')
code['number_of_iterations'] = code['number_of_iterations'] + paper_iterations[:1]
code['number_of_greedy_iterations'] = code['number_of_greedy_iterations'] + paper_iterations[1:]
check(len(code) >= 12, 'found %d defaults in Remeshing_options and Energy_weights' % len(code))

# The reference: the named-parameter block of graphcut_isotropic_remeshing().
header = open(source + '/include/CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h').read()
documented = 0
for name, default in re.findall(r'\\cgalParamNBegin\{(?:graphcut_parameters::)?(\w+)\}.*?\\cgalParamDefault\{(.*?)\}\s*\n',
                                header, re.S):
    if name in code and name != 'visitor':
        documented += 1
        check(numbers(default) == code[name],
              'reference manual: %s defaults to %s, the code to %s' % (name, default, code[name]))
check(documented >= 11, 'the reference documents the default of %d parameters' % documented)

# The user manual's table of parameters.
manual = open(source + '/doc/Graphcut_remeshing/Graphcut_remeshing.txt').read()
tabled = 0
for name, default in re.findall(r'<tr><td>`(\w+)`[^<]*</td><td>([^<]*)</td>', manual):
    if name in code:
        tabled += 1
        check(numbers(default) == code[name], 'user manual: %s defaults to %s, the code to %s' % (name, default, code[name]))
check(tabled >= 11, 'the user manual tables the default of %d parameters' % tabled)

# The tool's help.
help_text = subprocess.run([tool, '--help'], capture_output=True, text=True).stdout
options = {'--iterations': 'number_of_iterations', '--greedy-iterations': 'number_of_greedy_iterations',
           '--lambda-data': 'lambda_data', '--face-data-weight': 'face_data_weight', '--seed': 'random_seed'}
for option, name in options.items():
    m = re.search(re.escape(option) + r'\b.*?\(default ([^)]*)\)', help_text, re.S)
    check(m is not None and numbers(m.group(1)) == code[name],
          'graphcut_remesh --help: %s defaults to %s, the code to %s' % (option, m and m.group(1), code[name]))

for f in failures:
    print('FAIL: ' + f)
print('%d parameters in the code, %d in the reference, %d in the user manual: %s'
      % (len(code), documented, tabled, 'all agree' if not failures else '%d disagree' % len(failures)))
sys.exit(1 if failures else 0)
