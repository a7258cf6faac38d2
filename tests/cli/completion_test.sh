#!/usr/bin/env bash
# The bash completion (cli/flood.bash-completion) as a shell uses it: each case sets the words
# typed so far, calls the completion function and compares what it offers.
#   tests/cli/completion_test.sh FLOOD COMPLETION_SCRIPT
set -u
flood=$1
source "$2"
failures=0
expect() {  # expect "WANTED" WORD...
    local wanted=$1; shift
    COMP_WORDS=("$flood" "$@"); COMP_CWORD=$(( ${#COMP_WORDS[@]} - 1 )); COMPREPLY=()
    _flood
    local got="${COMPREPLY[*]}"
    if [[ $got != "$wanted" ]]; then
        echo "completion-test: '${*}' offered '$got', expected '$wanted'" >&2
        failures=$((failures + 1))
    fi
}
expect "triangulate trace transcript verify bench generate shrink check --help --version" ""
expect "triangulate trace transcript" tr
expect "--format" trace --fo
expect "jsonl bin" trace x.json --format ""
expect "--max-findings --max-input-bytes" check --ma
expect "--findings" check x.gpkg --fi
expect "star staircase steiner" generate st
expect "bowtie-star" generate bow
expect "multipolygon" triangulate x --per-feature m
expect "--seed" generate star 10 --se
[[ $(complete -p flood) == *"-F _flood"* ]] || { echo "completion-test: not registered" >&2; failures=$((failures + 1)); }
[ $failures -eq 0 ] && echo "completion-test: ok"
exit $((failures > 0))
