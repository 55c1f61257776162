#!/bin/sh
# Install LIGGGHTS 3.8.0 from Debian's packages (binary `liggghts`, serial or
# MPI). Idempotent: does nothing when `liggghts` is already on PATH.
#
#     validation/liggghts/install.sh
set -e
if command -v liggghts >/dev/null 2>&1; then
    echo "liggghts already installed: $(command -v liggghts)"
    exit 0
fi
SUDO=
[ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends liggghts
command -v liggghts
