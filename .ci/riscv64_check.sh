#!/usr/bin/env bash
# The main job's "other platforms" phase (CI leaves it out for time): the golden state hashes on
# RISC-V (riscv64): every example scene at every checkpoint, on one worker and on four,
# cross-compiled by Debian 12's g++-riscv64-linux-gnu and run under qemu-riscv64 (qemu-user), and
# the cross-built libraries' libm calls checked (.ci/cross_determinism.sh). The same golden file as
# the x86-64 builds must come out.
set -euo pipefail
exec "$(dirname "$0")/cross_determinism.sh" riscv64
