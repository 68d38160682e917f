#!/usr/bin/env bash
# Sums fuzz/logs/stats.tsv (written by long-session.sh) per target: runs,
# CPU seconds, wall seconds, executions, overall exec per CPU second, the
# largest cov and ft seen, and runs that crashed.
#
#   bash fuzz/stats.sh [SINCE]
#
# SINCE (an ISO time such as 2026-01-31T09:00:00Z) counts only the runs
# started at or after it, e.g. one round of long-session.sh (a full pass).
set -euo pipefail
cd "$(dirname "$0")"
SINCE=${1:-} python3 - <<'PY'
import csv, os
since = os.environ.get("SINCE", "")
rows = [r for r in csv.DictReader(open("logs/stats.tsv"), delimiter="\t") if r["start"] >= since]
per = {}
for r in rows:
    p = per.setdefault(r["target"], dict(runs=0, cpu=0.0, wall=0.0, execs=0, cov=0, ft=0, crashes=0))
    p["runs"] += 1
    p["cpu"] += float(r["cpu_s"] or 0)
    p["wall"] += float(r["wall_s"] or 0)
    p["execs"] += int(r["execs"] or 0)
    p["cov"] = max(p["cov"], int(r["cov"] or 0))
    p["ft"] = max(p["ft"], int(r["ft"] or 0))
    p["crashes"] += int(r["crashed"] or 0)
print("| target | runs | CPU time | wall time | executions | exec/s (per CPU s) | cov | ft | crashed runs |")
print("|---|---|---|---|---|---|---|---|---|")
tot = 0.0
for t, p in sorted(per.items()):
    rate = p["execs"] / p["cpu"] if p["cpu"] else 0
    tot += p["cpu"]
    print(f"| {t} | {p['runs']} | {p['cpu']/60:.1f} min | {p['wall']/60:.1f} min | {p['execs']} | {rate:.0f} | {p['cov']} | {p['ft']} | {p['crashes']} |")
print(f"\nTotal CPU time: {tot/3600:.2f} h")
PY
