# Sourced by submit-clip.sh. sh_quote ARG...: the arguments as one command line for POSIX sh,
# which sbatch --wrap runs (dash on Debian): each in single quotes, a ' inside written '\''.
# bash's printf %q is no use there: it writes $'...' for control bytes, which dash does not read.
sh_quote() {
    local arg line=
    for arg in "$@"; do
        line+="'${arg//\'/\'\\\'\'}' "
    done
    printf '%s' "${line% }"
}
