# Copyright (c) 2026 the Graphcut_remeshing developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""What the command-line tests share: counted checks, each failure printed as it happens, and the
summary line and exit code at the end."""
import sys

failures = []
checks = 0


def check(condition, message):
    global checks
    checks += 1
    if not condition:
        failures.append(message)
        print("FAIL: " + message)


def finish(name):
    """Prints the summary and exits with 1 when a check failed."""
    print("%s: %d checks, %d failed" % (name, checks, len(failures)))
    sys.exit(1 if failures else 0)
