# Sourced by run_loop.sh for --camera: the estimator on a real camera's frames, alone. The table
# simulator's truth would not match a real table, and the planner has no robot to stroke, so
# neither runs: camera_node (tools/camera_node/) publishes the frames, estimator_node tracks them,
# lcm-logger records what it published, and at the source's end the run prints what was seen.
#
#   camera_kind SOURCE
#     camera_node's option for SOURCE: --device for /dev/..., a number or a GStreamer pipeline
#     (a '!'), --images for a directory, --video for anything else
#   run_camera
#     runs the nodes on run_loop.sh's $camera (and $camera_model, $params, $log, $log_frames,
#     $json, $view, $view_port; the processes it starts in $pids, with start_viewer's) until
#     the source ends, or a signal (a live camera is stopped
#     with Ctrl-C); prints the camera's and the estimator's health and the estimator's tracks
#     (billiard node-status and billiard tracks of the log) on stderr, and with --json one object
#     on stdout; exits 0 after a whole video or directory, 1 when the source failed (its line
#     said why), 130 after a signal

camera_kind() {
  case "$1" in
    *'!'* | /dev/* | [0-9] | [0-9][0-9]) echo --device ;;
    *) if [ -d "$1" ]; then echo --images; else echo --video; fi ;;
  esac
}

run_camera() {
  if [ -z "${in_namespace:-}" ] && ! ip route get 239.255.76.67 >/dev/null 2>&1; then
    echo "run_loop: --camera needs UDP multicast between processes: a network namespace" \
         "(unshare -n) or a multicast route" >&2
    exit 1
  fi
  local camera_log=$log camera_err estimator_err logged=()
  camera_err=$(mktemp) estimator_err=$(mktemp)
  [ -n "$camera_log" ] || camera_log=$(mktemp --suffix=.lcm)
  # shellcheck disable=SC2317  # called by the trap
  camera_cleanup() {
    for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
    [ -n "${VIEW_FORWARDER:-}" ] && kill -TERM "$VIEW_FORWARDER" 2>/dev/null
    wait 2>/dev/null || true
    rm -f "$camera_err" "$estimator_err" "${VIEW_SOCKET:-}"
    [ -n "$log" ] || rm -f "$camera_log"
  }
  trap camera_cleanup EXIT
  stopped=false
  trap 'stopped=true' INT TERM

  # Without --log, what the summary reads: the states and the statuses, not the frames.
  if [ -z "$log" ]; then
    logged=(--channel 'TABLE_STATE|NODE_STATUS')
  elif [ "$log_frames" = none ]; then
    logged=(--channel CAMERA_IMAGE --invert-channels)
  fi
  lcm-logger --quiet --force "${logged[@]}" "$camera_log" >/dev/null 2>&1 &
  local logger=$!
  "$bin_dir/estimator_node" --params "$params" ${camera_model:+--camera "$camera_model"} \
    2>"$estimator_err" &
  pids+=($!)
  $view && start_viewer
  sleep 0.5  # the estimator and the logger subscribe
  "$bin_dir/camera_node" "$(camera_kind "$camera")" "$camera" --exit-at-end 2>"$camera_err" &
  local camera_node=$! status=0
  pids+=("$camera_node")
  wait "$camera_node" || status=$?
  if $stopped; then
    kill -TERM "$camera_node" 2>/dev/null || true
    wait "$camera_node" 2>/dev/null || true
  fi
  $stopped || wait_for_the_estimator "$camera_log"
  # (A Ctrl-C at a terminal has stopped it already, with the nodes.)
  kill -TERM "$logger" 2>/dev/null && wait "$logger" || true
  print_camera_summary "$camera_log" "$camera_err"
  $stopped && exit 130
  [ "$status" -eq 0 ] || exit 1
  exit 0
}

# On a busy machine the estimator lags behind the camera: polls the log $1 until it holds a state
# for every frame the camera published and the estimator did not refuse, or until no state has
# come for a quiet spell (a frame lost on the way), so that the tracks end where the video does.
wait_for_the_estimator() {
  local poll_s=0.2 quiet_polls=15 quiet=0 seen=-1 progress
  while progress=$(estimator_progress "$1"); do
    local states=${progress% *} frames=${progress#* }
    [ "$states" -ge "$frames" ] && return
    if [ "$states" -eq "$seen" ]; then
      quiet=$((quiet + 1))
      [ "$quiet" -ge "$quiet_polls" ] && return
    else
      quiet=0 seen=$states
    fi
    sleep "$poll_s"
  done
}

# "STATES FRAMES": the estimator's states in the log $1, and the frames it owes one for (the
# camera's published, less the estimator's refusals as its last status counts them); one frame
# more until the camera's last status, the one that says its source ended or failed, is logged.
estimator_progress() {
  local statuses tracks
  statuses=$("$bin_dir/billiard" node-status "$1" 2>/dev/null) || return 1
  tracks=$("$bin_dir/billiard" tracks "$1" 2>/dev/null) || return 1
  python3 - "$statuses" "$tracks" <<'PY'
import json, sys
statuses, tracks = json.loads(sys.argv[1]), json.loads(sys.argv[2])
def last(node):
    found = [p for p in statuses["processes"] if p["node"] == node]
    return found[-1] if found else {"published": 0, "dropped": 0}
camera = last("camera_node")
source_done = camera.get("counters", {}).get("source_state", 0) >= 2
owed = camera["published"] - last("estimator_node")["dropped"] + (0 if source_done else 1)
print(tracks["states"], owed)
PY
}

# What the run saw: the camera's last line, the nodes' health, the tracks; $json adds the object.
print_camera_summary() {
  local statuses tracks
  statuses=$("$bin_dir/billiard" node-status "$1")
  tracks=$("$bin_dir/billiard" tracks "$1")
  python3 - "$statuses" "$tracks" "$2" "$json" <<'PY'
import json, sys
statuses, tracks = json.loads(sys.argv[1]), json.loads(sys.argv[2])
lines = [l.rstrip("\n") for l in open(sys.argv[3]) if l.strip()]
said = [l.split(": ", 1)[1] for l in lines if l.startswith("camera_node: ") and l != "camera_node: stopped"]
source = said[-1] if said else ""
def last_of(node):
    found = [p for p in statuses["processes"] if p["node"] == node]
    return found[-1] if found else None
camera, estimator = last_of("camera_node"), last_of("estimator_node")
states = ("opening", "running", "ended", "failed")
if sys.argv[4] == "true":
    print(json.dumps({"source": source, "camera": camera, "estimator": estimator, "tracks": tracks}))
out = sys.stderr
print(f"camera: {source}", file=out)
if camera:
    state = camera["counters"].get("source_state", 0)
    print(f"camera_node: {camera['published']} frames published, {camera['dropped']} failed, "
          f"the source {states[state] if 0 <= state < 4 else state}", file=out)
# The states from the log; the refusals from the estimator's last status (a second old at most).
dropped = f"{estimator['dropped']} frames dropped" if estimator else "no status"
if estimator and estimator["dropped"]:
    dropped += f" (the last: {estimator['last_error']})"
print(f"estimator_node: {tracks['states']} states published; {dropped}", file=out)
print(f"{len(tracks['tracks'])} tracks over {tracks['seconds']:.2f} s, {tracks['balls_at_end']} balls "
      f"in the last state", file=out)
print(f"{'track':>5} {'class':>7} {'conf':>5} {'states':>6} {'first s':>8} {'last s':>7} "
      f"{'last x, y (m)':>16} {'speed m/s':>9}", file=out)
for t in tracks["tracks"]:
    vx, vy = t["last_velocity"]
    print(f"{t['id']:>5} {t['class']:>7} {t['class_confidence']:5.2f} {t['states']:>6} "
          f"{t['first_s']:8.2f} {t['last_s']:7.2f} ({t['last'][0]:6.3f}, {t['last'][1]:6.3f}) "
          f"{(vx * vx + vy * vy) ** 0.5:9.3f}", file=out)
PY
}
