#!/usr/bin/env bash
# A long fuzzing session: rotates through the fuzz targets, one libFuzzer
# process at a time at the lowest CPU priority, each for SECONDS_PER_RUN,
# for ROUNDS rounds (0 = until stopped). Run from anywhere:
#
#   bash fuzz/long-session.sh [SECONDS_PER_RUN] [ROUNDS] [TARGET...]
#
# Generated corpora go to fuzz/corpus/<target>/ (the committed seeds in
# fuzz/seeds/<target>/ are read as a second corpus directory), crashes to
# fuzz/artifacts/<target>/, logs to fuzz/logs/. Every run appends one line
# to fuzz/logs/stats.tsv:
#   target, start (UTC), CPU seconds (user+sys), wall seconds, executions,
#   exec/s (libFuzzer's average), cov, ft, corpus units, crashed (0/1)
# `bash fuzz/stats.sh` sums them per target.
#
# Builds with `--sanitizer none` (stable toolchain; see fuzz/README.md).
set -uo pipefail
cd "$(dirname "$0")"
seconds=${1:-600}
rounds=${2:-0}
shift 2 2>/dev/null || shift $#
chosen=("$@")
bin_dir=target/x86_64-unknown-linux-gnu/release
mkdir -p logs
[ -f logs/stats.tsv ] || printf 'target\tstart\tcpu_s\twall_s\texecs\texec_per_s\tcov\tft\tcorpus\tcrashed\n' > logs/stats.tsv
round=0
while [ "$rounds" -eq 0 ] || [ "$round" -lt "$rounds" ]; do
    round=$((round + 1))
    # The target list is read every round, so targets added meanwhile join.
    if [ ${#chosen[@]} -gt 0 ]; then
        targets=("${chosen[@]}")
    else
        mapfile -t targets < <(cargo fuzz list)
    fi
    for t in "${targets[@]}"; do
        # Rebuild if the sources changed; keep the previous binary if the
        # build fails (e.g. mid-edit).
        nice -n 19 cargo fuzz build --sanitizer none "$t" > "logs/build-$t.log" 2>&1 || true
        [ -x "$bin_dir/$t" ] || continue
        mkdir -p "corpus/$t" "artifacts/$t" "seeds/$t"
        start=$(date -u +%Y-%m-%dT%H:%M:%SZ)
        log="logs/$t-$(date -u +%Y%m%dT%H%M%S).log"
        /usr/bin/time -f '%U %S %e' -o "$log.time" \
            nice -n 19 "$bin_dir/$t" "corpus/$t" "seeds/$t" \
            -max_total_time="$seconds" -print_final_stats=1 -timeout=30 \
            -rss_limit_mb=2048 -artifact_prefix="artifacts/$t/" > "$log" 2>&1
        crashed=0
        grep -q -E '^==[0-9]+== ERROR|^SUMMARY: libFuzzer|panicked at|deadly signal|Test unit written' "$log" && crashed=1
        read -r user sys wall < <(tail -n 1 "$log.time")
        cpu=$(python3 -c "print(round($user + $sys, 1))")
        execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
        rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
        last=$(grep -E '^#[0-9]+' "$log" | grep 'cov:' | tail -n 1)
        cov=$(sed -n 's/.*cov: \([0-9]*\).*/\1/p' <<< "$last")
        ft=$(sed -n 's/.*ft: \([0-9]*\).*/\1/p' <<< "$last")
        corp=$(sed -n 's/.*corp: \([0-9]*\).*/\1/p' <<< "$last")
        if [ -z "$execs" ]; then
            execs=$(sed -n 's/^#\([0-9]*\).*/\1/p' <<< "$last")
        fi
        printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$t" "$start" "$cpu" "$wall" \
            "${execs:-0}" "${rate:-0}" "${cov:-0}" "${ft:-0}" "${corp:-0}" "$crashed" >> logs/stats.tsv
    done
done
