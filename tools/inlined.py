#!/usr/bin/env python3
"""Self instructions of one function, by the line of one source file that
holds them, inlined helpers counted where they are inlined.

usage: python3 tools/inlined.py FUNC FILE MAPRT ARG...

Runs MAPRT ARG... under callgrind (one instruction a position, as
tools/icount.sh: OMP_WAIT_POLICY=passive), takes the instructions FUNC
(and its recursive copies FUNC'N) executed itself, and charges each to the
outermost line of FILE (a path suffix, e.g. trace/trace.c) in its inline
chain as `objdump --inlines` gives it: so `vec3_normalize` inlined at
trace.c:243 counts at trace.c:243, not in vec.h. Prints the lines by
count with their share of FUNC's own instructions and of the whole run.
Needs valgrind and binutils' objdump.
"""
import collections
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile


def callgrind(argv):
    """Per-address self cost of every function, and the run's total."""
    fd, out = tempfile.mkstemp(prefix="inlined-", suffix=".cg")
    os.close(fd)
    try:
        env = dict(os.environ, OMP_WAIT_POLICY="passive")
        subprocess.run(["valgrind", "--tool=callgrind", "--dump-instr=yes", "--compress-pos=no",
                        "--compress-strings=no", "--callgrind-out-file=" + out] + argv,
                       env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        cost = collections.defaultdict(collections.Counter)
        total, fn, skip = 0, None, False
        with open(out) as f:
            for line in f:
                if line.startswith("summary:"):
                    total = int(line.split()[1])
                elif line.startswith("fn="):
                    fn, skip = line[3:].strip().split("'")[0], False
                elif line.startswith("calls="):
                    skip = True           # the next line is a call's inclusive cost
                elif fn and line.startswith("0x"):
                    if skip:
                        skip = False
                        continue
                    addr, _, n = line.split()
                    cost[fn][int(addr, 16)] += int(n)
        return cost, total
    finally:
        os.unlink(out)


def main():
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)   # quiet under head
    if len(sys.argv) < 4:
        sys.exit("usage: python3 tools/inlined.py FUNC FILE MAPRT ARG...")
    func, src, argv = sys.argv[1], sys.argv[2], sys.argv[3:]
    for tool in ("valgrind", "objdump"):
        if not shutil.which(tool):
            sys.exit("inlined: %s is not installed" % tool)
    cost, total = callgrind(argv)
    own = cost.get(func)
    if not own:
        sys.exit("inlined: %s executed no instructions of its own" % func)
    lo, hi = min(own), max(own) + 16
    dump = subprocess.run(["objdump", "-d", "-l", "--inlines", "--no-show-raw-insn",
                           "--start-address=%d" % lo, "--stop-address=%d" % hi, argv[0]],
                          capture_output=True, text=True, check=True).stdout
    by_line = collections.Counter()
    chain, after_insn = [], True
    for line in dump.splitlines():
        m = re.match(r"^\s+([0-9a-f]+):\s", line)
        if m:
            n = own.get(int(m.group(1), 16), 0)
            if n:
                outer = [c for c in chain if c.rsplit(":", 1)[0].endswith(src)]
                by_line[outer[-1] if outer else "(not in %s)" % src] += n
            after_insn = True
            continue
        m = re.match(r"^(?:inlined by )?(/\S+:\d+)", line)
        if m:                        # a location, innermost first
            if after_insn:
                chain = []
            chain.append(m.group(1))
            after_insn = False
    mine = sum(own.values())
    print("%s: %d instructions of its own, %.1f %% of %d" % (func, mine, 100.0 * mine / total, total))
    for where, n in by_line.most_common():
        print("%10d %5.1f %% %5.2f %%  %s" % (n, 100.0 * n / mine, 100.0 * n / total, where))


if __name__ == "__main__":
    main()
