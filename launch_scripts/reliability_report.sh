#!/usr/bin/env bash
# usage: launch_scripts/reliability_report.sh [--fuzz-seconds S] [--shots N] [--no-build]
#                                             [-h | --help]
#
# Measures how the controller holds under bad input, faults and load, and writes
# docs/reliability.md (and the raw figures, docs/reliability.json). Nothing in the report is
# typed by hand: every number comes from one of these runs.
#
#   --fuzz-seconds S  seconds per fuzz target (default 30)
#   --shots N         shots of the fault drill and of the lossy link (default 8, at least 2)
#   --no-build        run what build/ holds, without build.sh first
#   -h, --help        this text
#
#   fuzzing       fuzz/run_fuzzers.sh, S seconds per target
#   fault drill   launch_scripts/fault_drill.sh (kills, restarts, a new clock, a 10,000-request
#                 burst), N shots
#   lossy link    billiard loop (one process), N shots with 10 % of frames dropped, 5 % reordered
#                 and 5 % repeated, against the same shots without
#   edge cases    billiard edge-report (mu = 0, d = 0, eps = 1e-9, starved planner)
#
# About 3 minutes with the defaults; progress on stderr. Exit 1 when a step fails (a fuzz target
# that crashes among them); the report is then not written.
set -euo pipefail
source "$(dirname "$0")/script_support.sh"

fuzz_seconds=30 shots=8 build=true
while [ $# -gt 0 ]; do
  case "$1" in
    -h | --help) help_and_exit ;;
    --fuzz-seconds) need_number 1 "$@"; fuzz_seconds=$2; shift 2 ;;
    # The fault drill's least (fault_drill.sh --shots).
    --shots) need_number 2 "$@"; shots=$2; shift 2 ;;
    --no-build) build=false; shift ;;
    *) unknown_argument "$1" ;;
  esac
done
failures_are_internal
cd "$(dirname "$0")/.."
$build && bash launch_scripts/build.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "reliability_report: fuzzing, $fuzz_seconds s per target" >&2
bash fuzz/run_fuzzers.sh --seconds "$fuzz_seconds" --json >"$work/fuzz.json"
echo "reliability_report: fault drill" >&2
bash launch_scripts/fault_drill.sh --no-build --shots "$shots" >"$work/drill.json"
echo "reliability_report: lossy link" >&2
build/bin/billiard loop --shots "$shots" --seed 4 2>/dev/null >"$work/clean.json"
build/bin/billiard loop --shots "$shots" --seed 4 --drop-frames 0.1 \
  --reorder-frames 0.05 --duplicate 0.05 2>/dev/null >"$work/lossy.json"
echo "reliability_report: edge cases" >&2
build/bin/billiard edge-report 2>/dev/null >"$work/edge.json"

python3 - "$work" docs/reliability.json docs/reliability.md "$fuzz_seconds" <<'PY'
import json, sys, datetime, platform, os

work, json_out, md_out, fuzz_seconds = sys.argv[1:5]
load = lambda name: json.load(open(f"{work}/{name}.json"))
fuzz, drill, clean, lossy, edge = (load(n) for n in ("fuzz", "drill", "clean", "lossy", "edge"))
json.dump({"fuzz": fuzz, "drill": drill, "clean": clean, "lossy": lossy, "edge": edge},
          open(json_out, "w"), indent=1)

mm = lambda m: f"{1e3 * m:.2f}"
def shots_line(s):
    ok = sum(x["status"] == "ok" for x in s["shots"])
    return (f"{ok} of {len(s['shots'])} ok, miss median {mm(s['median_miss_m'])} mm, "
            f"max {mm(s['max_miss_m'])} mm")

out = []
w = out.append
w("# Reliability")
w("")
w(f"Produced by `launch_scripts/reliability_report.sh` on {datetime.date.today()} "
  f"({platform.machine()}, {os.cpu_count()} cores); the raw figures are in `reliability.json`. "
  "Do not edit by hand: run the script again.")
w("")

w("## Bad input")
w("")
total_runs = sum(t["runs"] for t in fuzz["targets"])
w(f"Every decode-and-check path and the image decoder under libFuzzer with AddressSanitizer and "
  f"UndefinedBehaviorSanitizer (`fuzz/`), {fuzz_seconds} s per target: **{total_runs:,} inputs, "
  f"{fuzz['crashes']} crashes**. A finding would be a crash, a sanitizer report, a leak, an "
  "exception, or an accepted payload that does not re-encode to the same bytes.")
w("")
w("| target | inputs | inputs/s | corpus | coverage | crashes |")
w("|---|---:|---:|---:|---:|---:|")
for t in fuzz["targets"]:
    w(f"| `{t['target']}` | {t['runs']:,} | {t['execs_per_sec']:,} | {t['corpus_size']} | "
      f"{t['coverage']} | {t['crashes']} |")
w("")

if "skipped" in drill:
    w("## Faults")
    w("")
    w(f"The fault drill was skipped: {drill['skipped']}.")
else:
    w("## Nodes killed and restarted")
    w("")
    w("`launch_scripts/fault_drill.sh`: the three nodes as separate processes over UDP multicast. "
      "Events (seconds from the start of session 1):")
    w("")
    for e in drill["events"]:
        w(f"- {e['t_s']} s: {e['event']}")
    w("")
    s1 = drill["session1"]
    c1 = s1.get("counters", {})
    w(f"- Session 1, through both kills: {shots_line(s1)}; {c1.get('resent', 0)} frames or "
      f"requests sent again while a node was down, {c1.get('shot_retried', 0)} shots asked again "
      "after a refusal that time cures (no state of the ball yet in a restarted planner).")
    w(f"- Session 3, a new table simulator after one killed mid-session (its clock starts again): "
      f"{shots_line(drill['session3'])}.")
    st = drill["stale"]
    w(f"- A ball state 2 s older than the requests (an estimator that stopped; the planner's max "
      f"state age is 1 s): {st['requests']} requests, answered "
      + ", ".join(f"{v} {k}" for k, v in sorted(st["statuses"].items())) + ".")
    w("")
    w("Each node process's last `NODE_STATUS` (from the drill's log, `billiard node-status`):")
    w("")
    w("| node | up s | received | dropped | published | counters | worst latency p99 |")
    w("|---|---:|---:|---:|---:|---|---:|")
    for p in drill["nodes"]:
        counters = ", ".join(f"{k} {v}" for k, v in sorted(p["counters"].items())) or "-"
        w(f"| {p['node']} | {p['uptime_s']:.1f} | {p['received']} | {p['dropped']} | "
          f"{p['published']} | {counters} | {p['max_latency_p99_us'] / 1e3:.2f} ms |")
    w("")
    b, b2, rss = drill["burst"], drill["second_burst"], drill["planner_rss_kb"]
    statuses = ", ".join(f"{v} {k}" for k, v in sorted(b["statuses"].items()))
    w("## Load")
    w("")
    w(f"`billiard burst`: {b['requests']:,} shot requests sent to the running planner in "
      f"{b['send_s']:.2f} s. **{b['answered']:,} answered, {b['unanswered']} unanswered**, "
      f"{b['answered_twice']} answered twice: {statuses}. The queue holds 32 requests; beyond "
      f"it a request is answered busy at once. All answers were in after {b['total_s']:.2f} s; "
      f"round trip p50 {b['latency_ms']['p50']:.0f} ms, p99 {b['latency_ms']['p99']:.0f} ms, "
      f"max {b['latency_ms']['max']:.0f} ms. A second burst: {b2['answered']:,} answered, "
      f"{b2['unanswered']} unanswered. Planner memory: {rss['before_burst'] / 1024:.1f} MB "
      f"before, {rss['after_burst'] / 1024:.1f} MB after the first burst, "
      f"{rss['after_second_burst'] / 1024:.1f} MB after the second (peak {rss['peak'] / 1024:.1f} "
      "MB).")
    w("")
w("## Lossy link")
w("")
c = lossy.get("counters", {})
w(f"The same {len(clean['shots'])} lockstep shots (one process, `billiard loop`), "
  "once over a clean link and once with frames dropped (10 %), held back behind the next (5 %) "
  "and sent twice (5 %), and requests sent twice (5 %):")
w("")
w(f"- clean: {shots_line(clean)}")
w(f"- lossy: {shots_line(lossy)}; {c.get('frame_dropped', 0)} frames dropped, "
  f"{c.get('frame_reordered', 0)} reordered, {c.get('frame_duplicated', 0)} repeated, "
  f"{c.get('request_duplicated', 0)} requests repeated")
w("")

w("## Parameters at the edge")
w("")
w("`billiard edge-report` (`planner/edge_report.h`): the approximate 5-DOF model over 8 s on five "
  "scenes, and eight plans, per parameter set. An ok plan is simulated again at the default "
  "tolerance; the miss is that simulation's.")
w("")
w("| set | valid | steps (max over scenes) | max energy rise J | plans ok | worst re-simulated miss of an ok | refusals |")
w("|---|---|---:|---:|---:|---:|---|")
wrong_ok = 0
energy = lambda j: "< 1e-15" if j < 1e-15 else f"{j:.1e}"  # below that, rounding
for s in edge["sets"]:
    sims = [x for x in s.get("simulations", []) if "steps" in x]
    steps = max((x["steps"] for x in sims), default=0)
    rise = max((x["max_energy_rise_J"] for x in sims), default=0.0)
    plans = s.get("plans", [])
    oks = [p for p in plans if p["status"] == "ok"]
    worst = max((p["resimulated_miss_m"] for p in oks), default=None)
    wrong_ok += sum(p["resimulated_miss_m"] > 1e-5 for p in oks)
    refusals = {}
    for p in plans:
        if p["status"] != "ok":
            refusals[p["status"]] = refusals.get(p["status"], 0) + 1
    ref = ", ".join(f"{v} {k}" for k, v in sorted(refusals.items())) or "-"
    reason = s.get("reason", "").removeprefix(s["name"] + ": ")
    w(f"| {s['name']} | {'yes' if s['valid'] else 'no: ' + reason} | "
      f"{steps if sims else '-'} | {energy(rise) if sims else '-'} | {len(oks)} of {len(plans)} | "
      f"{'-' if worst is None else f'{worst:.1e} m'} | {ref} |")
w("")
w(f"Ok plans that miss by more than 10 um when simulated again: **{wrong_ok}**.")
w("")
w("A starved planner says so:")
w("")
for case in edge["non_convergence"]:
    w(f"- {case['case']}: {case['status']}, \"{case['reason']}\"")
w("")
open(md_out, "w").write("\n".join(out))
PY
echo "reliability_report: wrote docs/reliability.md" >&2
