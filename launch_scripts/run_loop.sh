#!/usr/bin/env bash
# usage: launch_scripts/run_loop.sh [--game nine-ball|eight-ball|drill] [--players A,B]
#                                   [--racks N] [--shot-limit N]
#                                   [--shots N] [--seed S] [--noise on|off]
#                                   [--scene break|seeded|FILE]
#                                   [--pot K:P ...] [--params NAME|FILE] [--log FILE]
#                                   [--plant-params NAME|FILE] [--identify-every N]
#                                   [--identify LIST] [--plant-noise NAME|FILE] [--learn-noise]
#                                   [--spins LIST]
#                                   [--log-frames all|none]
#                                   [--lockstep | --realtime] [--view] [--view-port PORT]
#                                   [--json] [--no-build] [-h | --help]
#        launch_scripts/run_loop.sh --camera SOURCE [--camera-model FILE] [--params NAME|FILE]
#                                   [--log FILE] [--log-frames all|none] [--view]
#                                   [--view-port PORT] [--json] [--no-build]
#
# The closed loop: estimator_node, planner_node and table_sim_node over LCM, playing nine-ball
# (the default: one rack broken and played until it is cleared), or for N shots to random
# targets; prints the summary on stderr and, with --json, one JSON object on stdout. With
# --camera, the estimator on a real camera's frames instead, alone (below).
#
#   --game nine-ball|drill the game (the default without --shots or --scene): nine-ball, the
#                          rack of --seed broken and then played; drill, a seeded nine-ball
#                          layout (billiard play's) from ball in hand. Under nine-ball rules,
#                          the planner choosing every shot (shot_request_t::MODE_CHOOSE) from
#                          the estimator's view, the table executing it with the robot's noise,
#                          until the table is clear or the shot limit; prints every shot and the
#                          summary (pots per attempt, run-outs, balls per visit, fouls, decision
#                          time, the estimator's position error at each decision)
#   --game eight-ball      a match of eight-ball (the computational pool's rules: groups, called
#                          pots, the 8 last), ours against ours without --players
#   --players A,B          --game nine-ball or eight-ball: a match between two players (ours,
#                          ours-no-safety, no-lookahead, easiest-looking), the planner answering
#                          for both (each request names the player at the table); the table
#                          simulator referees (sim/rules: a miss or a foul hands the table over,
#                          three fouls in a row lose a nine-ball rack), rack k broken by A when k
#                          is even, by B when odd, with the game's stored break (billiard match's);
#                          prints who played each shot and each player's racks won (with the
#                          Wilson 95 % interval), break-and-runs, pots, attempts, safeties, fouls
#   --racks N              --game: racks played, of seeds S, S + 1, ... (default 1)
#   --shot-limit N         --game: the most shots of a rack (default 40)
#   --shots N              N shots to random targets instead of a game (default 20)
#   --seed S               seed of the targets (the racks) and of the noise, two streams of
#                          their own (default 1): the noise leaves the targets as they were
#   --noise on|off         the robot's execution noise (default off; on in a game)
#   --scene break|seeded|FILE
#                          one whole-table shot instead: the eight-ball rack of --seed (break) or
#                          a scene file at rest, the cue ball rolled into the ball nearest it;
#                          prints how the estimator tracked every ball (error, swaps). seeded:
#                          the pot of bench-pot's first layout from --seed x 1000 whose line
#                          is clear with a cut below 60 deg (billiard pot-layout --clear
#                          --max-cut 60), played as --pot plays it
#   --pot K:P              with --scene FILE or seeded: pot ball K (the scene's id) in pocket P
#                          (lower_left, lower_middle, lower_right, upper_left, upper_middle,
#                          upper_right) instead: planned by planner_node from the estimator's
#                          view, executed with the robot's noise; prints whether K dropped in P
#                          and where the cue ball stopped against the plan. Again for more pots,
#                          played in turn from where the last left the balls
#   --params NAME|FILE     the parameter set of all three nodes: pool (default), paper, snooker,
#                          carom, or a JSON file (docs/simulation.md)
#   --plant-params NAME|FILE  the table simulator plays a table of these parameters (the same
#                          table and balls as --params) while the estimator and the planner keep
#                          --params: a table the controller does not know
#   --identify-every N     the planner identifies the table online: every N of its shots it fits
#                          the sliding friction and the rolling resistance to its own tracked
#                          shots and plans with them (default 5 with --plant-params, else 0:
#                          never); the summary shows each fit after the shots
#   --identify LIST        the constants the planner identifies (default mu,rolling; see
#                          planner_node --identify)
#   --plant-noise NAME|FILE  the robot executes its strokes with this noise (a name of
#                          sim/params/noise/ or a JSON file of its format) instead of --noise's,
#                          while the planner keeps choosing for the noise it was told of; the
#                          summary shows the noise the robot drew (RMS over its strokes)
#   --learn-noise          the planner measures its own strokes' noise from the launches the
#                          estimator tracks and chooses for it (planner_node --learn-noise); the
#                          summary shows the noise learned, with its intervals; the shots to
#                          random targets then vary their spin (--spins natural,stun,follow,draw)
#   --spins LIST           the spin styles of the shots to random targets in turn (natural,
#                          stun, follow, draw; default natural): the tip heights vary, so that
#                          the spin the slide shows tells the tip's error from the speed's
#   --log FILE             record every message with lcm-logger into FILE
#   --log-frames all|none  with --log: record the CAMERA_IMAGE frames or not (default all)
#   --lockstep             wait for the estimator's state of each frame: deterministic (default)
#   --realtime             pace the frames by the wall clock
#   --view                 a live view of the table in a browser while the loop runs
#                          (viewer_node): prints its address, http://127.0.0.1:PORT/, on stderr;
#                          with --realtime the shots go at the camera's pace, to be watched;
#                          run from a terminal, the view keeps the last table after the run
#                          until Ctrl-C (from a script it closes with the run)
#   --view-port PORT       the view's port on this host (default 8765; implies --view)
#   --camera SOURCE        the estimator on the frames of SOURCE instead of the loop:
#                          camera_node (a V4L2 camera /dev/videoN or N, a GStreamer pipeline
#                          with a '!', a video file, or a directory of images) and
#                          estimator_node alone, no planner and no table simulator (whose
#                          truth would not be the real table's); runs to the end of the video
#                          or the images (a camera until Ctrl-C) and prints the camera's and the
#                          estimator's health and every track the estimator published: its
#                          class, when it was seen, where it was last and how fast (--json: one
#                          object, {"source", "camera", "estimator", "tracks"}). Exit 1 when the
#                          source failed (a video cut short, a file that is no video, a camera
#                          that stalled: camera_node's line says which). Not with --game,
#                          --shots, --scene, --pot or --plant-params
#   --camera-model FILE    with --camera: the estimator's camera model (billiard calibrate's
#                          JSON); default: the table simulator's overhead camera at 1280x720
#   --json                 the summary as one JSON object on stdout
#   --no-build             run what build/ holds, without build.sh first (which builds the three
#                          nodes and billiard alone: the tests are test.sh's)
#   -h, --help             this text
#
# An installed copy (PREFIX/share/billiard/launch_scripts/run_loop.sh) runs PREFIX/bin/'s nodes
# and builds nothing.
#
# --log FILE: a relative FILE is in the caller's directory; with --log-frames none the log leaves
# out the frames, which are nearly all of its bytes, and it cannot be replayed through the
# estimator (replay.sh). A log that cannot be written stops the run before it starts (exit 2);
# one that records nothing, or a logger that dies, fails it at the end (exit 1, after the
# summary). A session the table simulator refuses (the nodes run other physics) exits 3.
#
# LCM traffic stays on this host: inside a private network namespace with multicast routed to
# loopback when one can be made (unshare -n), else UDP multicast with ttl=0, else (no multicast
# route at all) the three nodes in one process on LCM's in-memory provider, which says so.
set -euo pipefail
source "$(dirname "$0")/script_support.sh"

shots="" game="" players="" racks=1 shot_limit=40 seed=1 noise="" scene="" params=pool plant="" identify_every="" identify=mu,rolling log="" log_frames=all clock=--lockstep json=false build=true plant_noise="" learn_noise=() spins=""
pots=()
view=false view_port=8765 camera="" camera_model=""
while [ $# -gt 0 ]; do
  case "$1" in
    -h | --help) help_and_exit ;;
    --shots) need_number 1 "$@"; shots=$2; shift 2 ;;
    --game) need_value "$@"; game=$2; shift 2 ;;
    --players) need_value "$@"; players=$2; shift 2 ;;
    --racks) need_number 1 "$@"; racks=$2; shift 2 ;;
    --shot-limit) need_number 1 "$@"; shot_limit=$2; shift 2 ;;
    --seed) need_number 0 "$@"; seed=$2; shift 2 ;;
    --noise) need_value "$@"; noise=$2; shift 2 ;;
    # A scene file, like --log, is the caller's path; "break" is a name.
    --scene)
      need_value "$@"; scene=$2
      case "$scene" in break | seeded) ;; *) scene=$(realpath -m -- "$2") ;; esac
      shift 2 ;;
    --pot) need_value "$@"; pots+=(--pot "$2"); shift 2 ;;
    # Before the cd to the repository below: a relative path is the caller's.
    --log) need_value "$@"; log=$(realpath -m -- "$2"); shift 2 ;;
    # A parameter file is the caller's path too; a name has no slash and no .json.
    --params)
      need_value "$@"
      case "$2" in */* | *.json) params=$(realpath -m -- "$2") ;; *) params=$2 ;; esac
      shift 2 ;;
    --plant-params)
      need_value "$@"
      case "$2" in */* | *.json) plant=$(realpath -m -- "$2") ;; *) plant=$2 ;; esac
      shift 2 ;;
    --identify-every) need_number 0 "$@"; identify_every=$2; shift 2 ;;
    --identify) need_value "$@"; identify=$2; shift 2 ;;
    --plant-noise)
      need_value "$@"
      case "$2" in */* | *.json) plant_noise=$(realpath -m -- "$2") ;; *) plant_noise=$2 ;; esac
      shift 2 ;;
    --learn-noise) learn_noise=(--learn-noise); shift ;;
    --spins) need_value "$@"; spins=$2; shift 2 ;;
    --log-frames) need_value "$@"; log_frames=$2; shift 2 ;;
    --lockstep) clock=--lockstep; shift ;;
    --realtime) clock=--realtime; shift ;;
    --view) view=true; shift ;;
    --view-port) need_number 1 "$@"; view=true; view_port=$2; shift 2 ;;
    # A device, a number or a pipeline is a name; a file or a directory is the caller's path.
    --camera)
      need_value "$@"
      case "$2" in *'!'* | /dev/* | [0-9] | [0-9][0-9]) camera=$2 ;; *) camera=$(realpath -m -- "$2") ;; esac
      shift 2 ;;
    --camera-model) need_value "$@"; camera_model=$(realpath -m -- "$2"); shift 2 ;;
    --json) json=true; shift ;;
    --no-build) build=false; shift ;;
    # Added by enter_private_network when the script runs itself again in its namespace.
    --in-namespace) in_namespace=true; shift ;;
    *) unknown_argument "$1" ;;
  esac
done
if [ -n "$camera" ]; then
  [ -z "$game$shots$scene$plant${pots[*]}" ] ||
    usage_error "--camera runs the estimator alone: not with --game, --shots, --scene, --pot or --plant-params"
  case "$camera" in
    *'!'*) ;;
    [0-9] | [0-9][0-9]) [ -e "/dev/video$camera" ] || usage_error "no camera at '/dev/video$camera'" ;;
    *) [ -e "$camera" ] || usage_error "no camera, video or directory at '$camera'" ;;
  esac
  [ -z "$camera_model" ] || [ -f "$camera_model" ] ||
    usage_error "no camera model at '$camera_model'"
elif [ -n "$camera_model" ]; then
  usage_error "--camera-model needs --camera"
fi
# Without --shots or --scene the loop plays the game this controller exists for.
[ -z "$camera" ] && [ -z "$game" ] && [ -z "$shots" ] && [ -z "$scene" ] && game=nine-ball
case "$game" in
  "" | nine-ball | eight-ball | drill) ;;
  *) usage_error "--game must be nine-ball, eight-ball or drill, not '$game'" ;;
esac
if [ -n "$players" ] && [ "$game" != nine-ball ] && [ "$game" != eight-ball ]; then
  usage_error "--players plays a match: with --game nine-ball or eight-ball"
fi
if [ -n "$game" ] && { [ -n "$shots" ] || [ -n "$scene" ]; }; then
  usage_error "--game plays racks: not with --shots or --scene"
fi
[ -n "$shots" ] || shots=20
[ -n "$noise" ] || { [ -n "$game" ] && noise=on || noise=off; }
case "$noise" in
  on|off) ;;
  *) usage_error "--noise must be on or off, not '$noise'" ;;
esac
case "$log_frames" in
  all|none) ;;
  *) usage_error "--log-frames must be all or none, not '$log_frames'" ;;
esac
[ -n "$identify_every" ] || { [ -n "$plant" ] && identify_every=5 || identify_every=0; }
if [ ${#pots[@]} -gt 0 ] && { [ -z "$scene" ] || [ "$scene" = break ]; }; then
  usage_error "--pot needs --scene FILE or --scene seeded"
fi
# A log that cannot be written is said before anything is built or started: opened for appending
# (an existing file keeps its bytes until the logger starts), and a new one removed again.
if [ -n "$log" ]; then
  log_existed=false
  [ -e "$log" ] && log_existed=true
  reason=$( { : >>"$log"; } 2>&1 ) || usage_error "cannot write the log '$log': ${reason##*: }"
  $log_existed || rm -f "$log"
fi
# The live view's port, said before anything is built or started when something on this host
# answers on it already (another run's view): in the namespace below every port is free, and
# the forwarder on this host would fail out of sight.
if $view && [ -z "${in_namespace:-}" ] && (exec 3<>"/dev/tcp/127.0.0.1/$view_port") 2>/dev/null; then
  usage_error "--view-port $view_port: the port is in use on this host (another run's live view?); choose another"
fi
failures_are_internal
cd "$(dirname "$0")/.."
$installed && build=false
# What the loop runs, and nothing more: the tests, fuzzers and benchmarks are test.sh's.
$view && view_target=(--target viewer_node) || view_target=()
if [ -n "$camera" ]; then
  nodes=(--target estimator_node --target camera_node)
else
  nodes=(--target estimator_node --target planner_node --target table_sim_node)
fi
$build && bash launch_scripts/build.sh "${nodes[@]}" --target billiard "${view_target[@]}"

# The view out of the private network namespace below: this host's port forwarded (socat) to a
# Unix socket, which the namespace shares with the host, and there to the viewer's port. Started
# here, before the namespace, and stopped by the run inside it.
if $view && [ -z "${in_namespace:-}" ] && unshare -n true 2>/dev/null; then
  command -v socat >/dev/null || { echo "run_loop: --view needs socat (setup.sh installs it)" >&2; exit 1; }
  export VIEW_SOCKET
  VIEW_SOCKET=$(mktemp -u "${TMPDIR:-/tmp}/billiard-view.XXXXXX.sock")
  socat "TCP-LISTEN:$view_port,bind=127.0.0.1,reuseaddr,fork" "UNIX-CONNECT:$VIEW_SOCKET" \
    2>/dev/null &
  export VIEW_FORWARDER=$!
  echo "run_loop: the live view is at http://127.0.0.1:$view_port/" >&2
fi

source launch_scripts/lcm_network.sh
# The viewer_node of --view, on its port; in the namespace, reached through the socket above.
start_viewer() {
  "$bin_dir/viewer_node" --params "$params" "${planner_table[@]}" --port "$view_port" 2>/dev/null &
  pids+=($!)
  if [ -n "${VIEW_SOCKET:-}" ]; then
    socat "UNIX-LISTEN:$VIEW_SOCKET,fork" "TCP:127.0.0.1:$view_port" 2>/dev/null &
    pids+=($!)
  else
    echo "run_loop: the live view is at http://127.0.0.1:$view_port/" >&2
  fi
}
if [ -n "$camera" ]; then
  source launch_scripts/camera_mode.sh
  enter_private_network launch_scripts/run_loop.sh --no-build --camera "$camera" \
    ${camera_model:+--camera-model "$camera_model"} --params "$params" ${log:+--log "$log"} \
    --log-frames "$log_frames" $($json && echo --json) $($view && echo --view-port "$view_port")
  pids=()
  run_camera
fi
# A learning loop's strokes vary their tip height: natural roll alone cannot tell the tip's
# error from the speed's (docs/identification.md).
[ ${#learn_noise[@]} -gt 0 ] && [ -z "$spins" ] && spins=natural,stun,follow,draw
playing=(--shots "$shots" ${spins:+--spins "$spins"})
[ -n "$game" ] && playing=(--game "$game" ${players:+--players "$players"} --racks "$racks" --shot-limit "$shot_limit")
enter_private_network launch_scripts/run_loop.sh --no-build "${playing[@]}" --seed "$seed" \
  --noise "$noise" --params "$params" ${plant:+--plant-params "$plant"} ${plant_noise:+--plant-noise "$plant_noise"} "${learn_noise[@]}" --identify-every "$identify_every" --identify "$identify" ${scene:+--scene "$scene"} "${pots[@]}" ${log:+--log "$log"} --log-frames "$log_frames" "$clock" $($json && echo --json) $($view && echo --view-port "$view_port")
# Without a namespace, separate processes only where multicast reaches back over loopback;
# otherwise one process on LCM's in-memory provider.
in_process=false
if [ -z "${in_namespace:-}" ]; then
  if ! ip route get 239.255.76.67 >/dev/null 2>&1; then
    in_process=true
    echo "run_loop: no network namespace and no multicast route: the three nodes run in one" \
         "process over memq://${log:+ (nothing to record: --log needs multicast)}" \
         "$($view && echo "(and nothing to view: --view needs multicast)")" >&2
    log=""
  else
    echo "run_loop: no network namespace; UDP multicast with ttl=0" >&2
  fi
fi

pids=()
summary_file=$(mktemp) logger_err=$(mktemp) planner_err=$(mktemp)
cleanup() {
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  [ -n "${VIEW_FORWARDER:-}" ] && kill -TERM "$VIEW_FORWARDER" 2>/dev/null
  wait 2>/dev/null || true
  rm -f "$summary_file" "$logger_err" "$planner_err" "${VIEW_SOCKET:-}" "${layout_file:-}"
}
trap cleanup EXIT

# A seeded layout becomes a scene file, and its pot the one played unless --pot names others.
if [ "$scene" = seeded ]; then
  layout_file=$(mktemp --suffix=.json)
  # Cuts below 60 deg: the pots a player calls makeable, whose margins the robot's noise leaves.
  layout=$("$bin_dir/billiard" pot-layout --seed "$seed" --clear --max-cut 60 --params "$params" \
             --out "$layout_file" --json) || exit 1
  scene=$layout_file
  if [ ${#pots[@]} -eq 0 ]; then
    pots=(--pot "$(python3 -c 'import json, sys; j = json.loads(sys.argv[1]); print(j["ball"], j["pocket"], sep=":")' "$layout")")
  fi
fi

if [ -n "$log" ]; then
  without_frames=()
  [ "$log_frames" = none ] && without_frames=(--channel CAMERA_IMAGE --invert-channels)
  # The logger is the one receiver lockstep does not wait for: starved of the CPU while the
  # planner decides, its socket's 4 MB (net.core.rmem_max) overflowed and a frame the estimator
  # answered was never recorded, so the replay lacked it. Where it may, it runs ahead of the nodes.
  logger_priority=()
  [ "$(id -u)" = 0 ] && logger_priority=(nice -n -10)
  "${logger_priority[@]}" lcm-logger --quiet --force "${without_frames[@]}" "$log" >/dev/null 2>"$logger_err" &
  logger=$!
  pids+=($logger)
fi
# The planner pots on the scene's table (a scene that does not load is the session's to refuse).
planner_table=()
if [ -n "$scene" ] && [ "$scene" != break ]; then
  table=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1])).get("table", ""))' \
            "$scene" 2>/dev/null) || table=""
  [ -n "$table" ] && planner_table=(--table "$table")
fi
if ! $in_process; then
  "$bin_dir/estimator_node" --params "$params" 2>/dev/null &
  pids+=($!)
  "$bin_dir/planner_node" --params "$params" "${planner_table[@]}" \
    --identify-every "$identify_every" --identify "$identify" "${learn_noise[@]}" >/dev/null 2>"$planner_err" &
  pids+=($!)
  $view && start_viewer
  sleep 0.5  # the nodes subscribe
fi

sim_clock=""
[ "$clock" = --realtime ] && sim_clock=--realtime
# A fit between shots takes seconds; the simulator waits for its answer that long. A game's
# choice (safeties, the second level) takes a second or two, and on a machine busy with other
# work several times that: the simulator's 10 s would end a sound run.
identifying=()
[ -n "$game" ] && identifying=(--reply-timeout 60)
[ "$identify_every" -gt 0 ] && identifying=(--reply-timeout 120)
$in_process && identifying+=(--identify-every "$identify_every" "${learn_noise[@]}")
# In the background, so that a signal reaches the trap at once and the cleanup stops it too.
session=("$bin_dir/table_sim_node")
$in_process && session=("$bin_dir/billiard" loop)
"${session[@]}" --params "$params" ${plant:+--plant-params "$plant"} "${identifying[@]}" "${playing[@]}" --seed "$seed" --noise "$noise" \
  ${plant_noise:+--plant-noise "$plant_noise"} ${scene:+--scene "$scene"} "${pots[@]}" $sim_clock >"$summary_file" &
pids+=($!)
status=0
wait $! || status=$?
# The session's own refusal (3) and a signal (130) are the run's; anything else is its failure.
case $status in
  0) ;;
  2 | 3 | 130) exit $status ;;
  *) echo "run_loop: table_sim_node failed (exit $status)" >&2; exit 1 ;;
esac
summary=$(cat "$summary_file")
# The logger stops (and writes what it holds) before the log is looked at.
log_failure=""
if [ -n "$log" ]; then
  if ! kill -0 "$logger" 2>/dev/null; then
    log_failure="lcm-logger stopped during the run: $(tail -n 1 "$logger_err")"
  else
    kill -TERM "$logger"
    wait "$logger" || log_failure="lcm-logger failed: $(tail -n 1 "$logger_err")"
  fi
  [ -n "$log_failure" ] || [ -s "$log" ] || log_failure="it recorded nothing"
fi
$json && echo "$summary"
# The summary from its file: a game's is longer than a command line may be.
python3 - "$summary_file" >&2 <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
pots = s.get("scene", {}).get("pots", [])
game = s.get("game")
if game:
    match = "players" in game
    for k, rack in enumerate(game["racks"]):
        if match:
            won = f"{rack['winner']} wins ({rack['reason']})" if rack["winner"] else f"undecided ({rack['reason']})"
            print(f"rack {k} (seed {rack['seed']}): {rack['breaker']} breaks; {won} in "
                  f"{len(rack['shots'])} shots, {rack['visits']} visit(s)"
                  f"{', a break-and-run' if rack['break_and_run'] else ''}")
        else:
            print(f"rack {k} (seed {rack['seed']}): {'cleared' if rack['cleared'] else 'not cleared'} in "
                  f"{len(rack['shots'])} shots, {rack['visits']} visit(s){', a run-out' if rack['run_out'] else ''}")
        print("  (" + ("player: who shot; " if match else "") +
              "call: the ball and pocket called, or none for a safety or the fallback; p: the chance the "
              "choice gave it; potted: the balls that dropped, * when the called one did; ms: the "
              "decision's time; est mm: the estimator's position error at the decision, rms)")
        who = f" {'player':>16}" if match else ""
        print(f"{'shot':>4} {'visit':>5}{who} {'call':>18} {'p':>5} {'potted':>10} {'foul':>24} {'ms':>6} {'est mm':>6}")
        for shot in rack["shots"]:
            c = shot.get("called")
            call = ("break" if shot["break"] else f"{c['ball']} {c['pocket']}" if c else
                    "safety" if shot.get("safety") else "none" if shot["status"] == "ok" else shot["status"])
            p = f"{c['predicted']:.2f}" if c else ""
            potted = ",".join(str(b) for b in shot["potted"]) + (" *" if shot["called_potted"] else "")
            hand = " (in hand)" if shot["ball_in_hand"] else ""
            who = f" {shot['player']:>16}" if match else ""
            print(f"{shot['number']:>4} {shot['visit']:>5}{who} {call + hand:>18} {p:>5} {potted:>10} "
                  f"{shot.get('foul_reason', ''):>24} {shot['decision_ms']:6.0f} "
                  f"{shot['estimator']['position_rms_mm']:6.2f}")
    g = game["summary"]
    print(f"{g['cleared']} of {g['racks']} racks cleared, {g['run_outs']} run-outs (racks cleared in "
          f"one visit, the break's); "
          f"{g['pots']} of {g['attempts']} attempts potted ({100 * g['pots_per_attempt']:.0f} %), "
          f"{g['balls_per_visit']:.2f} balls per visit, {g['fouls']} fouls; decision "
          f"{g['median_decision_ms']:.0f} ms median ({g['max_decision_ms']:.0f} max); the estimator "
          f"{g['median_position_rms_mm']:.2f} mm rms median at the decisions ({g['max_position_error_mm']:.2f} "
          f"max), {g['misidentified_ball_decisions']} balls misidentified in {g['decisions']} decisions")
    for p in game.get("players", []):
        lo, hi = p["interval95"]
        print(f"{p['name']}: {p['racks_won']} racks won of {g['racks']} ({100 * p['win_rate']:.0f} %, "
              f"95 % {lo:.2f} to {hi:.2f}), {p['break_and_runs']} break-and-runs, {p['pots']} pots "
              f"of {p['attempts']} attempts, {p['safeties']} safeties, {p['fouls']} fouls")
if not pots and not game:
    print(f"{'shot':>4} {'target':>16} {'final':>16} {'miss mm':>9} {'plan ms':>8}  status")
for i, shot in enumerate([] if pots or game else s["shots"]):
    t, f = shot["target"], shot["final"]
    print(f"{i:>4} ({t[0]:6.3f},{t[1]:6.3f}) ({f[0]:6.3f},{f[1]:6.3f}) {1e3*shot['miss_m']:9.2f} "
          f"{shot['plan_ms']:8.2f}  {shot['status']}")
for i, p in enumerate(pots):
    line = f"pot {i}: ball {p['ball']} in {p['pocket']}: {p['status']}"
    if p["status"] == "ok":
        dropped = "potted" if p["potted"] else f"missed (dropped in {p['dropped']})" if p["dropped"] else "missed"
        m, w, r = p["margin_deg"], p["speed_window"], p["planned_cue_rest"]
        line += (f", {p['kind']}, margin {m[0]:.2f}/{m[1]:.2f} deg, speed {w[0]:.2f}-{w[1]:.2f} m/s: "
                 f"{dropped}{', scratch' if p['scratch'] else ''}; the cue ball rests at "
                 f"({p['cue_rest'][0]:.3f}, {p['cue_rest'][1]:.3f}), "
                 f"{1e3*p['cue_rest_error_m']:.1f} mm from the plan's ({r[0]:.3f}, {r[1]:.3f}); "
                 f"planned in {p['plan_ms']:.1f} ms")
    else:
        line += f" ({p['reason']})"
    print(line)
if not pots and not game:
    print(f"median miss {1e3*s['median_miss_m']:.2f} mm, max {1e3*s['max_miss_m']:.2f} mm, "
          f"mean {1e3*s['mean_miss_m']:.2f} +- {1e3*s['stddev_miss_m']:.2f} mm, {s['wall_s']:.1f} s")
if "plant" in s:
    print(f"the table played {s['plant']}; the nodes ran their own parameters")
if "plant_noise" in s:
    print(f"the robot executed with the noise {s['plant_noise']}; the planner was not told")
if "drawn_noise" in s:
    d = s["drawn_noise"]
    print(f"the robot drew over its {d['strokes']} strokes (RMS): heading {d['heading_deg']:.3f} deg, "
          f"speed {100*d['speed_fraction']:.2f} %, tip {d['tip_mm']:.3f} mm")
if "scene" in s:
    scene, tracking = s["scene"], s["scene"]["tracking"]
    pocketed = [f"{b['id']} ({b['pocketed']})" for b in scene["balls"] if b["pocketed"]]
    print(f"{scene['name']}: {scene['events']} events, pocketed: {', '.join(pocketed) or 'none'}")
    print(f"{'ball':>4} {'frames':>6} {'lost':>5} {'rms mm':>7} {'max mm':>7} {'misnamed':>8} {'at end':>6}")
    for b in tracking["balls"]:
        print(f"{b['id']:>4} {b['frames']:>6} {b['lost']:>5} {b.get('rms_error_mm', float('nan')):7.2f} "
              f"{b.get('max_error_mm', float('nan')):7.2f} {b['misnamed'] + b['unnamed']:>8} "
              f"{'right' if b['named_at_end'] else 'wrong':>6}")
    print(f"tracking: rms {tracking['rms_error_mm']:.2f} mm, max {tracking['max_error_mm']:.2f} mm, "
          f"{tracking['swaps']} swaps, {tracking['reacquired']} tracks re-acquired, "
          f"{tracking['lost_ball_frames']} ball-frames without a track; identity: "
          f"{tracking['misnamed_ball_frames']} ball-frames misnamed, "
          f"{tracking['unnamed_ball_frames']} unnamed, {tracking['named_at_end']} of "
          f"{len(tracking['balls'])} balls named right at the end")
PY
# The planner's online identifications, each after the shots it was fitted to, and the noise it
# learned last.
grep -h "identif" "$planner_err" >&2 || true
grep -h "learned noise" "$planner_err" | tail -n 1 >&2 || true
if [ -n "$log_failure" ]; then
  echo "run_loop: the log '$log' is not a record of the run: $log_failure" >&2
  exit 1
fi
# The live view keeps the last table for a player at a terminal until Ctrl-C (the run's outcome
# is already printed, and its status 0); a script's run closes it at once.
if $view && [ -t 0 ] && ! $in_process; then
  echo "run_loop: the run is over; the live view keeps its last table at" \
       "http://127.0.0.1:$view_port/ until Ctrl-C" >&2
  # Ctrl-C closes the view: neither the cut sleep nor a node already gone is the run's failure.
  trap 'set +eE; trap - ERR; exit 0' INT TERM
  while :; do sleep 1 || true; done
fi
