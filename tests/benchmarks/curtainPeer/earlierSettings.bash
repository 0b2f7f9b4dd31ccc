# The one reader of earlierSettings (sourced by ./ladder and
# ../warmStart/run): earlier_settings [GROUP...] prints the edits, all of
# them or those of the groups named, one per line as FILE<TAB>ENTRY<TAB>VALUE
# (VALUE may hold spaces), in the file's order. An entry two groups set
# (PIMPLE/maxCo: 2 before the courant change, 5 before the steps change)
# is printed once, with the first group's value: the older setting. A line
# with fewer than four fields is refused with its number.
earlier_settings()
{
    awk -v groups="$*" -v f="${BASH_SOURCE[0]%.bash}" '
        BEGIN { n = split(groups, g); for (i = 1; i <= n; i++) want[g[i]] = 1 }
        /^[[:space:]]*(#|$)/ { next }
        NF < 4 { printf "%s:%d: expected GROUP FILE ENTRY VALUE, found \"%s\"\n", f, FNR, $0 > "/dev/stderr"
                 bad = 1; exit 1 }
        (n == 0 || ($1 in want)) && !(($2 SUBSEP $3) in seen) {
            seen[$2, $3] = 1
            v = $4; for (i = 5; i <= NF; i++) v = v " " $i
            printf "%s\t%s\t%s\n", $2, $3, v }
        END { exit bad }' "${BASH_SOURCE[0]%.bash}"
}
