#!/usr/bin/env bash
# Gradescope's setup.sh: runs once, as root, when the autograder's image is built. The zip holds
# this file, run_autograder and impulse/ (a copy of the impulse repository).
set -euo pipefail
cd /autograder/source/impulse
./scripts/build.sh   # installs the Debian/Ubuntu packages it needs, then builds build/demos/impulse
