#!/usr/bin/python3
"""Unit typing is free (a performance design rule, not NFR1), checked in the code rather than the clock.

The typing kernel (verification/bench/typing_kernel.hpp) is one template compiled twice with
identical flags: run_bridge through the unit-typed model layer (bridge::Model, Boost.Units) and
run_plain on the same formulas in plain doubles. tamias_bench times the two, but on a shared
host the timing moves by +-2 %, the size of the limit itself. The instructions do not move: if the
typing cost anything, the typed kernel would compute more, call helpers the optimiser left out of
line, or spill more. Oracle: the plain-double instantiation of the same template.

Checks, for each clone (AVX2 and baseline) the two builds share:
  * the typed kernel makes no more calls than the plain one;
  * it executes no more floating-point arithmetic (add, sub, mul, div, sqrt, min, max, compare,
    logic, blend);
  * it has at most 1 % more instructions in all (padding not counted). Two compilations of
    equivalent code may allocate registers and schedule differently; that costs moves, not
    arithmetic, and measured 0.1 % when this check was written (docs/performance.md).

usage: check_typing_instructions.py OBJDUMP LIBRARY
"""

import re
import subprocess
import sys

FUNCTION = re.compile(r"^[0-9a-f]+ <tamias_bench::typing::run_(bridge|plain)\(.*\)"
                      r"(?: \[clone \.(\w+)\])?>:$")
# Packed or scalar double/single arithmetic, with or without the VEX prefix, and FMA.
ARITHMETIC = re.compile(r"^v?(add|sub|mul|div|sqrt|min|max|cmp\w*|and|andn|or|xor|blendv?)"
                        r"(pd|sd|ps|ss)$|^vfn?m(add|sub)\w+$")
TOLERANCE = 0.01


def kernels(disassembly):
    """{(clone, build): [mnemonic, ...]} for run_bridge and run_plain, padding dropped."""
    found = {}
    current = None
    for line in disassembly.splitlines():
        m = FUNCTION.match(line)
        if m:
            current = found.setdefault((m.group(2) or "only", m.group(1)), [])
            continue
        if not line.strip():
            current = None
            continue
        if current is None or ":\t" not in line:
            continue
        text = line.split(":\t", 1)[1].split()
        if not text or any("nop" in t for t in text) or text[:2] == ["xchg", "%ax,%ax"]:
            continue
        # Prefixes (data16, cs, lock, rep) stand before the mnemonic.
        while len(text) > 1 and text[0] in ("data16", "cs", "ds", "lock", "rep", "repz", "repnz",
                                            "notrack", "bnd"):
            text = text[1:]
        current.append(text[0])
    return found


def main():
    objdump, library = sys.argv[1], sys.argv[2]
    out = subprocess.run([objdump, "-d", "--no-show-raw-insn", "-C", library],
                         check=True, capture_output=True, text=True).stdout
    found = kernels(out)
    # The resolver only picks a clone at load time: not the kernel.
    clones = sorted({c for c, _ in found
                     if c != "resolver" and (c, "bridge") in found and (c, "plain") in found})
    if not clones:
        print("no run_bridge/run_plain pair found in", library)
        return 1
    failed = False
    for clone in clones:
        typed = found[(clone, "bridge")]
        plain = found[(clone, "plain")]
        def both(kind):
            return tuple(sum(1 for k in build if kind(k)) for build in (typed, plain))

        calls = both(lambda k: k.startswith("call"))
        arith = both(ARITHMETIC.match)
        total = (len(typed), len(plain))
        checks = [
            ("calls", calls, calls[0] <= calls[1]),
            ("floating-point arithmetic", arith, arith[0] <= arith[1]),
            ("instructions", total, total[0] <= total[1] * (1 + TOLERANCE)),
        ]
        for name, (t, p), ok in checks:
            print(f"clone {clone}: {name}: typed {t}, plain {p}: {'ok' if ok else 'FAILED'}")
            failed |= not ok
        if arith[1] == 0:
            print(f"clone {clone}: no arithmetic recognised in the plain kernel: the parse is wrong")
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
