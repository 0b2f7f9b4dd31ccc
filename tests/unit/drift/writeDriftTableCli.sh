#!/bin/sh
# writeDriftTable: a shipped table's rows handed over as a sweep JSON come back
# as the same file; malformed sweeps are refused naming the file and the
# entry, and leave the output as it was.
set -eu
tool="$1"; table="$2"; work="$3"
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$work"; mkdir -p "$work"
# the sweep JSON of the shipped table (header pairs and rows as numbers)
python3 - "$table" "$work/sweep.json" <<'PY'
import csv, json, sys
head, rows = [], []
with open(sys.argv[1]) as f:
    lines = f.read().splitlines()
for l in lines[1:]:
    if not l.startswith("#"):
        break
    k, _, v = l[2:].partition(":")
    head.append([k.strip(), v.strip()])
body = [l for l in lines if not l.startswith("#")]
for r in list(csv.reader(body))[1:]:
    rows.append([r[0]] + [float(x) for x in r[1:]])
json.dump({"header": head, "rows": rows}, open(sys.argv[2], "w"))
PY
"$tool" -in "$work/sweep.json" -out "$work/table.csv" > "$work/log" 2>&1 || { cat "$work/log"; fail "sweep refused"; }
cmp -s "$table" "$work/table.csv" || fail "the table written from its own rows differs from $table"
cp "$work/table.csv" "$work/keep.csv"
# a row dropped without a '# missing:' line, a bad number, no rows
python3 - "$work/sweep.json" "$work" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
t = dict(s); t["rows"] = s["rows"][:-1]; json.dump(t, open(sys.argv[2] + "/holed.json", "w"))
t = dict(s); t["rows"] = [s["rows"][0][:7] + ["abc"] + s["rows"][0][8:]] + s["rows"][1:]
json.dump(t, open(sys.argv[2] + "/nan.json", "w"))
json.dump({"header": s["header"]}, open(sys.argv[2] + "/norows.json", "w"))
PY
refused() {  # refused <input> <text>
    if "$tool" -in "$work/$1" -out "$work/table.csv" > "$work/log" 2>&1; then fail "accepted $1"; fi
    grep -q "$2" "$work/log" || { cat "$work/log"; fail "$1: error does not say '$2'"; }
    cmp -s "$work/keep.csv" "$work/table.csv" || fail "$1: the table was changed"
}
refused holed.json "grid incomplete"
refused nan.json "rows\[0\].vc_over_vg"
refused norows.json "rows"
echo "writeDriftTable CLI: all checks passed"
