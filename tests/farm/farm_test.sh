#!/usr/bin/env bash
# scripts/farm end to end on a one-node Slurm cluster (scripts/slurm-local): a 12-frame
# animation, a 4-way sample split of a still and the still in 2x2 crop tiles with an AOV,
# each compared with the same render on one machine; then re-runs that must submit only
# what was deleted.
# usage: farm_test.sh REPO BIN_DIR WORK_DIR
set -euo pipefail
repo="$1"
bin="$2"
work="$3"
rm -rf "$work"
mkdir -p "$work"
# Short: munge's socket lives here, and a socket path is limited to 108 bytes.
state="$(mktemp -d /tmp/inkray-farm-test.XXXXXX)"
# Not the ports scripts/slurm-local takes by default, so a cluster someone runs is left
# alone; the first free pair from 6937 (one left by a killed run is skipped).
port=6937
while (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null || (exec 3<>"/dev/tcp/127.0.0.1/$((port + 1))") 2>/dev/null; do
  port=$((port + 2))
  ((port < 6999)) || { echo "FAIL: no free pair of ports from 6937 to 6999"; exit 1; }
done
slurm=("$repo/scripts/slurm-local" --dir "$state" --port "$port" --timeout 60)
# The interpreter itself, not a wrapper on PATH: one check runs farm with an empty PATH.
python="$(python3 -c 'import sys; print(sys.executable)')"
farm=("$python" "$repo/scripts/farm" --bin "$bin")
render=("$bin/inkray-render")
scene="$repo/tests/data/farm/anim12.json"
still="$repo/scenes/cornell_outlines.json"
start=$SECONDS

cleanup() {
  "${slurm[@]}" stop >/dev/null 2>&1 || true
  rm -rf "$state"
}
trap cleanup EXIT

step() { echo "== $* ($((SECONDS - start)) s)"; }

show_logs() {
  local f
  for f in "$work"/*/*.farm/logs/*.out "$state"/slurmctld.log "$state"/slurmd.log; do
    [ -f "$f" ] || continue
    echo "----- last lines of $f"
    tail -n 20 "$f"
  done
}

fail() {
  echo "FAIL: $*"
  show_logs
  exit 1
}

# Runs scripts/farm, echoes what it says (all of its output when it fails) and leaves
# the output in $farm_out.
run_farm() {
  farm_out="$("${farm[@]}" "$@" 2>&1)" || { echo "$farm_out"; fail "scripts/farm $*"; }
  grep '^farm:' <<<"$farm_out" || true
}

# Job ids that the last scripts/farm printed as submitted.
submitted() { sed -n 's/^farm: submitted job \([0-9]*\).*/\1/p' <<<"$farm_out" | tr '\n' ' '; }

# Waits until every job (and array task) has ended, then fails unless all completed with
# exit code 0. $1: the number of job records expected (array tasks count one each).
wait_jobs() {
  local expected="$1" ids="$2" deadline=$((SECONDS + 150)) records
  [ -n "${ids// /}" ] || fail "scripts/farm submitted no job"
  while :; do
    records="$(for id in $ids; do scontrol show job -o "$id"; done 2>&1)" || fail "scontrol: $records"
    if ! grep -qE 'JobState=(PENDING|RUNNING|CONFIGURING|COMPLETING|SUSPENDED|REQUEUED|RESIZING)' <<<"$records"; then
      break
    fi
    ((SECONDS < deadline)) || fail "jobs $ids still queued or running after 150 s:
$(squeue)"
    sleep 1
  done
  local ok count
  ok="$(grep -cE 'JobState=COMPLETED .*ExitCode=0:0' <<<"$records" || true)"
  count="$(grep -c 'JobId=' <<<"$records" || true)"
  if [ "$ok" != "$expected" ] || [ "$count" != "$expected" ]; then
    grep -oE 'JobId=[0-9]+ (ArrayJobId=[0-9]+ ArrayTaskId=[0-9-]+ )?JobName=[^ ]+|JobState=[A-Z_]+ Reason=[^ ]+|ExitCode=[0-9:]+' <<<"$records" | paste - - - || true
    fail "$ok of $expected job records completed with exit code 0 ($count records)"
  fi
}

expect_output() {
  grep -qF -- "$1" <<<"$farm_out" || fail "scripts/farm did not say '$1'"
}

# ---------------------------------------------------------------- errors, no cluster needed
step "errors and dry runs"
if out="$("${farm[@]}" "$work/missing.json" -o "$work/x.png" 2>&1)"; then fail "a missing scene was accepted"; fi
grep -q "scene not found" <<<"$out" || fail "missing scene: $out"
if out="$("${farm[@]}" "$scene" -o "$work/f_####.png" --frames 5-1 2>&1)"; then fail "--frames 5-1 was accepted"; fi
grep -q "before the first" <<<"$out" || fail "bad range: $out"
if out="$("${farm[@]}" "$still" -o "$work/x.png" --slices 20 --spp 16 2>&1)"; then fail "20 slices of 16 spp were accepted"; fi
if out="$(PATH=/nonexistent "${farm[@]}" "$scene" -o "$work/f_####.png" 2>&1)"; then
  fail "no sbatch on PATH was accepted"
fi
grep -q "sbatch not found" <<<"$out" || fail "no sbatch: $out"
run_farm "$still" -o "$work/dry/x.png" --slices 4 --spp 16 --dry-run
expect_output "--dependency=afterok:<job id of"
[ ! -e "$work/dry" ] || fail "--dry-run wrote $work/dry"

# ---------------------------------------------------------------- the cluster
step "starting the local Slurm cluster"
"${slurm[@]}" start || fail "the local Slurm cluster did not start (its log is above)"
export SLURM_CONF="$state/slurm.conf"

step "submitting"
frames_args=("$scene" -o "$work/frames/anim_####.png" --frames 1-12 --width 64 --height 48 --spp 4)
run_farm "${frames_args[@]}"
frame_jobs="$(submitted)"
# 80 samples: the slices after the first start at 20, 40 and 60, after the line decisions
# are all made (sample 17 here), so they read them from the decisions job's file.
still_args=("$still" -o "$work/still/cornell.pfm" --slices 4 --spp 80 --width 96 --height 96
  --lines-svg "$work/still/cornell.svg")
run_farm "${still_args[@]}"
still_jobs="$(submitted)"
tiles_args=("$still" -o "$work/tiles/cornell.pfm" --aov "depth=$work/tiles/depth.pfm" --tiles 2x2 --spp 16
  --width 96 --height 96)
run_farm "${tiles_args[@]}"
tiles_jobs="$(submitted)"

# The one-machine renders, while the cluster works.
step "rendering the references on one machine"
mkdir -p "$work/ref"
"${render[@]}" "$scene" --frames 1-12 -o "$work/ref/anim_####.png" --width 64 --height 48 --spp 4 -q
"${render[@]}" "$still" -o "$work/ref/cornell.pfm" --spp 80 --width 96 --height 96 -q \
  --lines-svg "$work/ref/cornell.svg"
"${render[@]}" "$still" -o "$work/ref/tiles.pfm" --aov "depth=$work/ref/depth.pfm" --spp 16 --width 96 \
  --height 96 -q

step "waiting for jobs $frame_jobs$still_jobs$tiles_jobs"
wait_jobs 12 "$frame_jobs"
wait_jobs 6 "$still_jobs"  # the line decisions, 4 slices, the merge
wait_jobs 5 "$tiles_jobs"

step "comparing"
for f in $(seq -f '%04g' 1 12); do
  [ -f "$work/frames/anim_$f.png" ] || fail "frame $f was not written"
  cmp "$work/frames/anim_$f.png" "$work/ref/anim_$f.png" || fail "frame $f differs from the one-machine render"
done
[ "$(find "$work/still/cornell.farm/partials" -name '*.exr' | wc -l)" = 4 ] || fail "expected 4 partial images"
[ -f "$work/still/cornell.farm/partials/line_decisions.bin" ] || fail "the line decisions were not written"
# inkray-merge promises the image of one render of all the samples, exactly.
differing=()
for pair in still/cornell.pfm:ref/cornell.pfm tiles/cornell.pfm:ref/tiles.pfm tiles/depth.pfm:ref/depth.pfm; do
  echo "$work/${pair%%:*} against $work/${pair#*:}:"
  "$python" "$repo/tests/farm/compare_pfm.py" "$work/${pair%%:*}" "$work/${pair#*:}" 0 0 || differing+=("${pair%%:*}")
done
((${#differing[@]} == 0)) || fail "merged images differ from the one-machine renders: ${differing[*]}"
# The merged film is the one-machine film, so its lines as vectors are too.
cmp "$work/still/cornell.svg" "$work/ref/cornell.svg" || fail "the merged render's SVG differs from the one-machine one"

# ---------------------------------------------------------------- re-runs
step "re-running"
run_farm "${frames_args[@]}"
expect_output "nothing to submit"
run_farm "${still_args[@]}"
expect_output "nothing to submit"
rm "$work/tiles/depth.pfm"
run_farm "${tiles_args[@]}" --dry-run
expect_output "skipped 4 of 4 partial images"
grep -q "^sbatch .*inkray-cornell-merge" <<<"$farm_out" || fail "a missing AOV does not merge again"
rm "$work"/frames/anim_000{3,4,5,9}.png
run_farm "${frames_args[@]}" --chunk 2
expect_output "skipped 8 of 12 frames"
expect_output "array 0-2"  # 3-4, 5 and 9
wait_jobs 3 "$(submitted)"
for f in 0003 0004 0005 0009; do
  cmp "$work/frames/anim_$f.png" "$work/ref/anim_$f.png" || fail "re-rendered frame $f differs"
done

step "passed"
