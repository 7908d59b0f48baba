# SPDX-License-Identifier: MIT
# The JSON document a bench suite printed (the checking script's first argument), and a
# check that stops the test with what failed and the document.
import json
import sys


def document(test):
    d = json.loads(sys.argv[1])

    def check(ok, what):
        if not ok:
            sys.exit(f"{test}: {what}: {d}")

    return d, check
