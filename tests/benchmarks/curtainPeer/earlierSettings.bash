# The one reader of earlierSettings (sourced by ./ladder and
# ../warmStart/run): earlier_settings [GROUP] prints the edits, all of them
# or one group's, one per line as FILE<TAB>ENTRY<TAB>VALUE (VALUE may hold
# spaces); a line with fewer than four fields is refused with its number.
earlier_settings()
{
    awk -v g="$1" -v f="${BASH_SOURCE[0]%.bash}" '
        /^[[:space:]]*(#|$)/ { next }
        NF < 4 { printf "%s:%d: expected GROUP FILE ENTRY VALUE, found \"%s\"\n", f, FNR, $0 > "/dev/stderr"
                 bad = 1; exit 1 }
        g == "" || $1 == g { v = $4; for (i = 5; i <= NF; i++) v = v " " $i
                             printf "%s\t%s\t%s\n", $2, $3, v }
        END { exit bad }' "${BASH_SOURCE[0]%.bash}"
}
