#!/usr/bin/env bash
# The CI fuzz step: installs cargo-fuzz if missing, checks the fuzz crate
# (fmt, clippy), builds every target and runs each for FUZZ_SECONDS
# (default 60) starting from the committed seeds in fuzz/seeds/<target>/.
# Any crash, panic, timeout or out-of-memory fails the step.
#
# `-seed=1` fixes libFuzzer's random seed, but runs still diverge (the
# corpus is read in directory order, and two runs of one binary on one
# machine differ within 65 536 inputs), so a CI run may try inputs no local
# run did: fuzz longer locally before landing (README.md, "A long
# session"). Time per input is bounded by the targets' budgets (see
# README.md), far below `-timeout=30` even on a loaded machine.
#
# `-report_slow_units=30`: libFuzzer writes an input slower than 10 s as
# a "slow-unit" artifact, which this step counts as a finding; the limit
# per input is the 30 s timeout, so slow units are reported from there (a
# loaded CI machine can take several times a quiet one's seconds). Inputs
# stay far below it by the pair-tick budgets: the one that took 21 s here
# (a snapshot whose warm-start impulse sent its balls flying) is bounded
# since the budgets estimate every tick before stepping it, and it is now
# a seed of snapshot_restore, so every run of this step tries it again.

# `--sanitizer none`: CI has only a stable toolchain, and AddressSanitizer
# (cargo-fuzz's default) needs nightly's -Zsanitizer. The library forbids
# unsafe code, so the sanitizer would watch only the dependencies; the
# coverage instrumentation, panics (debug assertions and overflow checks
# are on) and libFuzzer's timeout and RSS limits work on stable.
set -euo pipefail
cd "$(dirname "$0")"
seconds=${FUZZ_SECONDS:-60}

if ! cargo fuzz --version >/dev/null 2>&1; then
    cargo install cargo-fuzz --locked --version 0.13.2
fi
cargo fuzz --version

cargo fmt --manifest-path Cargo.toml -- --check
cargo clippy --manifest-path Cargo.toml --all-targets --locked -- -D warnings

cargo fuzz build --sanitizer none
# Each run writes new corpus entries to a scratch directory, so the
# committed seeds stay as they are.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for target in $(cargo fuzz list); do
    echo "-- fuzzing $target for ${seconds}s"
    mkdir -p "$scratch/$target" "$scratch/artifacts/$target"
    status=0
    cargo fuzz run --sanitizer none "$target" "$scratch/$target" "seeds/$target" -- \
        -seed=1 -max_total_time="$seconds" -timeout=30 -report_slow_units=30 -rss_limit_mb=2048 \
        -print_final_stats=1 -artifact_prefix="$scratch/artifacts/$target/" \
        > "$scratch/$target.log" 2>&1 || status=$?
    grep -E '^#[0-9]+[[:space:]]+(INITED|DONE)|^stat::|^Done ' "$scratch/$target.log" || true
    if [ "$status" -ne 0 ] || [ -n "$(ls -A "$scratch/artifacts/$target")" ]; then
        tail -n 60 "$scratch/$target.log" >&2
        echo "fuzz target $target failed; artifacts:" >&2
        ls -l "$scratch/artifacts/$target" >&2
        for f in "$scratch/artifacts/$target"/*; do
            [ -f "$f" ] && base64 -w0 "$f" >&2 && echo >&2
        done
        exit 1
    fi
done
echo "fuzz: every target ran ${seconds}s without a finding"
