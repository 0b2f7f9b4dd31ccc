#!/bin/sh
# The checkout stands alone: no file names a folder beside it, every table
# in data/ is documented in data/README.md, and the shipped defaults and
# tools take their templates from etc/templates, not from a tutorial.
# Usage: check.sh PROJECT_DIR
set -u
root="$1"
cd "$root" || exit 1
fail=0
files() {
    if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
        git ls-files
    else
        find . -type f ! -path './build/*' ! -path './.deps/*' ! -path './platforms/*' ! -path './run/*' | sed 's#^\./##'
    fi
}
# The reference folder that sits beside a development checkout; the
# pattern is split so that this file does not match itself.
beside='sha''red'
hits=$(files | grep -v '^tests/validation/selfContained/' \
    | xargs grep -I -n -E "\.\./$beside|$beside/(data|notes|seeds)" 2>/dev/null)
if [ -n "$hits" ]; then
    echo "FAIL: files name a folder outside the checkout:"; echo "$hits"; fail=1
fi
for f in data/*.csv; do
    b=$(basename "$f")
    grep -q "\`$b\`" data/README.md || { echo "FAIL: data/README.md does not describe $b"; fail=1; }
done
hits=$(grep -rn 'template *"tutorials/\|template=tutorials/' etc/defaults cases 2>/dev/null)
if [ -n "$hits" ]; then
    echo "FAIL: a shipped table or dictionary takes its template from a tutorial:"; echo "$hits"; fail=1
fi
hits=$(grep -n 'tutorials/' applications/utilities/curtainCase/curtainCase applications/utilities/buildDriftTable/buildDriftTable src/drum/*/*.cpp 2>/dev/null)
if [ -n "$hits" ]; then
    echo "FAIL: a tool or library defaults to a tutorial:"; echo "$hits"; fail=1
fi
[ "$fail" = 0 ] && echo "selfContained: ok"
exit "$fail"
