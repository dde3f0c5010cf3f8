#!/bin/bash
# Profiles the code llvmpipe compiles at run time (release Mesa ignores GALLIVM_DEBUG, so there is no
# other way to see it): starts a fragpath command, waits until it renders, copies its anonymous
# executable mappings (the JIT code) out of the process with gdb, samples it with `perf record -e
# cpu-clock` and writes an annotated disassembly: every instruction with its sample count and share.
# The shader's out-of-line functions (llvmpipe calls one per buffer texture for texelFetch) end in a
# `ret`; the summary lists their sample shares.
#
# usage: tools/jit-profile.sh OUTDIR WAIT_S SAMPLE_S -- COMMAND...
#   e.g. tools/jit-profile.sh /tmp/jitprof 12 15 -- build/fragpath bench --suite --scenes sphere-100k --runs 40 --spp 8
# Needs gdb, perf, objdump, python3; ptrace and perf access to the process (root, or
# kernel.yama.ptrace_scope=0 and a low kernel.perf_event_paranoid).
# The command is killed when sampling ends. Output: OUTDIR/jit_<start>.bin (code), jit_<start>.s
# (objdump), annotated.txt ("address samples percent instruction"), summary.txt (per function, then
# the hottest instructions).
set -euo pipefail
if [ $# -lt 5 ] || [ "$4" != "--" ]; then
    sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'
    exit 2
fi
out=$1 wait_s=$2 sample_s=$3
shift 4
mkdir -p "$out"
"$@" > "$out/command.log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
sleep "$wait_s"
kill -0 $pid 2>/dev/null || { echo "the command ended before sampling started" >&2; exit 1; }

# Anonymous executable mappings: "start-end perms offset dev inode" with no path.
mapfile -t maps < <(awk '$2 ~ /x/ && NF == 5 {print $1}' /proc/$pid/maps)
perf record -q -e cpu-clock -p $pid -o "$out/perf.data" -- sleep "$sample_s" > /dev/null 2>&1
gdb_args=()
for m in "${maps[@]}"; do
    gdb_args+=(-ex "dump memory $out/jit_${m%-*}.bin 0x${m%-*} 0x${m#*-}")
done
gdb -p $pid -batch "${gdb_args[@]}" > "$out/gdb.log" 2>&1
perf script -i "$out/perf.data" -F ip 2> /dev/null | awk '{print $1}' > "$out/ips.txt"
[ -s "$out/ips.txt" ] || { echo "perf recorded no samples (see kernel.perf_event_paranoid)" >&2; exit 1; }
for m in "${maps[@]}"; do
    objdump -D -b binary -m i386:x86-64 --adjust-vma=0x${m%-*} "$out/jit_${m%-*}.bin" > "$out/jit_${m%-*}.s"
done

python3 - "$out" <<'EOF'
import collections, glob, re, sys
out = sys.argv[1]
ips = collections.Counter(int(l, 16) for l in open(f"{out}/ips.txt") if l.strip())
total = sum(ips.values())
rows = []  # (address, samples, instruction), every mapping in address order
for path in sorted(glob.glob(f"{out}/jit_*.s")):
    for l in open(path):
        m = re.match(r"\s*([0-9a-f]+):\s+(?:[0-9a-f]{2} )+\s*(.*)", l)
        if m and m.group(2).strip():
            a = int(m.group(1), 16)
            rows.append((a, ips.get(a, 0), m.group(2).strip()))
with open(f"{out}/annotated.txt", "w") as f:
    for a, c, ins in rows:
        f.write(f"{a:x} {c:7d} {100.0 * c / total:6.2f}  {ins}\n")
in_jit = sum(c for _, c, _ in rows)
with open(f"{out}/summary.txt", "w") as f:
    f.write(f"samples {total}, in the dumped JIT code {in_jit} ({100.0 * in_jit / total:.1f} %)\n\n")
    f.write("functions (code up to each ret): first address, instructions, samples, share\n")
    start = 0
    for i, (a, c, ins) in enumerate(rows):
        if ins.startswith("ret"):
            s = sum(r[1] for r in rows[start:i + 1])
            if s:
                f.write(f"  {rows[start][0]:x} {i + 1 - start:6d} {s:7d} {100.0 * s / total:5.1f} %\n")
            start = i + 1
    f.write("\nhottest instructions\n")
    for a, c, ins in sorted(rows, key=lambda r: -r[1])[:40]:
        f.write(f"  {a:x} {c:7d} {100.0 * c / total:5.2f} %  {ins}\n")
print(open(f"{out}/summary.txt").read())
EOF
