#!/usr/bin/env bash
# The Slurm job array, without a cluster (ctest label `grader`):
#   grader/tests/slurm_test.sh GRADER SOURCE_DIR
# - the array's tasks, run here with SLURM_ARRAY_TASK_ID set (two at a time, as on a
#   cluster), then the collect step, give byte for byte the roster.csv of one roster;
# - a task run again skips what it graded; one missing task leaves its students
#   "not graded" and makes the collect step exit 1;
# - grader/slurm/submit submits the array and the collect job after it (a stand-in sbatch
#   records the calls), and sbatch itself, where installed, accepts both scripts'
#   directives (--test-only against a one-node configuration with no controller to ask).
set -uo pipefail
grader=$1 src=$2
slurm=$src/grader/slurm
cases=$src/grader/tests/submissions/02-sphere
fail=0
bad() { echo "FAILED: $*"; fail=1; }
ok() { echo "ok: $*"; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
dir=$tmp/submissions
mkdir -p "$dir/ada" "$dir/bea" "$dir/cy/02-sphere"
cp "$src"/reference/02-sphere/*.cc "$src"/reference/02-sphere/*.hh "$dir/ada"/ 2>/dev/null
cp -r "$src"/assignments/02-sphere/. "$dir/bea"/
cp "$src"/reference/02-sphere/*.cc "$src"/reference/02-sphere/*.hh "$dir/cy/02-sphere"/ 2>/dev/null
patch --batch --silent -p1 -d "$dir/cy/02-sphere" -i "$cases/inward-normal/bug.patch" || bad "the planted bug does not apply"
tar -czf "$dir/cy.tar.gz" -C "$dir/cy" 02-sphere && rm -rf "$dir/cy"
echo "no archive" >"$dir/dee.zip"

# One roster: the CSV to match.
"$grader" roster 02 "$dir" --out "$tmp/roster" -j 2 >"$tmp/roster.log" 2>&1 || { bad "the roster failed:"; cat "$tmp/roster.log"; }

# The array: 3 tasks for 4 submissions, two at a time, each on one CPU, then the collect step.
export VL_GRADER=$grader VL_ASSIGNMENT=02 VL_SUBMISSIONS=$dir VL_OUT=$tmp/array SLURM_ARRAY_TASK_COUNT=3 SLURM_CPUS_PER_TASK=1
task() { SLURM_ARRAY_TASK_ID=$1 bash "$slurm/grade-array.sbatch" >"$tmp/task$1.log" 2>&1 || bad "task $1 failed: $(cat "$tmp/task$1.log")"; }
task 0 & task 1 & wait
task 2
bash "$slurm/collect.sbatch" >"$tmp/collect.log" 2>&1 || { bad "the collect step failed:"; cat "$tmp/collect.log"; }
if cmp -s "$tmp/roster/roster.csv" "$tmp/array/roster.csv"; then
  ok "3 array tasks and the collect step write the roster's roster.csv, byte for byte"
else
  bad "the array's CSV differs from the roster's:"; diff "$tmp/roster/roster.csv" "$tmp/array/roster.csv"
fi
grep -q '^"ada","graded",100,' "$tmp/array/roster.csv" && grep -q '^"bea","graded",0,' "$tmp/array/roster.csv" &&
  grep -q '^"dee","did not build",0,' "$tmp/array/roster.csv" || { bad "the array's scores:"; cat "$tmp/array/roster.csv"; }

# A task run again (a requeue) grades nothing new.
task 1
grep -q "in shard-1-of-3; 1 already graded and unchanged; grading 0 with" "$tmp/task1.log" &&
  ok "a task run again skips what it graded" || { bad "a requeued task:"; cat "$tmp/task1.log"; }

# Only tasks 0 and 2 of 3 ran: the collect step names task 1's student and exits 1.
export VL_OUT=$tmp/partial
task 0
task 2
if bash "$slurm/collect.sbatch" >"$tmp/collect2.log" 2>&1; then bad "collect exited 0 with a task missing"; fi
grep -q '^"bea","not graded",' "$tmp/partial/roster.csv" && grep -q "1 not graded yet" "$tmp/collect2.log" &&
  ok "a missing task leaves its student 'not graded' and the collect step exits 1" ||
  { bad "a missing task:"; cat "$tmp/collect2.log" "$tmp/partial/roster.csv"; }

# Without the variables, a task says what is missing.
if env -u VL_OUT bash "$slurm/grade-array.sbatch" >"$tmp/novar.log" 2>&1; then bad "a task without VL_OUT ran"; fi
grep -q "VL_OUT is not set" "$tmp/novar.log" || { bad "a task without VL_OUT: the message:"; cat "$tmp/novar.log"; }
unset VL_GRADER VL_ASSIGNMENT VL_SUBMISSIONS VL_OUT SLURM_ARRAY_TASK_COUNT SLURM_CPUS_PER_TASK

# submit, with a stand-in sbatch that records its arguments and the variables it passes on.
mkdir -p "$tmp/bin"
cat >"$tmp/bin/sbatch" <<'EOF'
#!/usr/bin/env bash
n=$(( $(cat "$SBATCH_LOG.count" 2>/dev/null || echo 0) + 1 )); echo $n >"$SBATCH_LOG.count"
echo "call $n: $* | VL_OUT=$VL_OUT VL_TASKS=$VL_TASKS VL_GRADER_ARGS=$VL_GRADER_ARGS" >>"$SBATCH_LOG"
echo "$((4100 + n));cluster"
EOF
chmod +x "$tmp/bin/sbatch"
if PATH=$tmp/bin:$PATH SBATCH_LOG=$tmp/sbatch.log VL_GRADER=$grader \
     bash "$slurm/submit" 02 "$dir" "$tmp/submitted" --tasks 2 --weaker-sandbox -- --partition=teach >"$tmp/submit.log" 2>&1; then
  if grep -q "call 1: --parsable --array=0-1 --chdir=$tmp/submitted --export=ALL --partition=teach $slurm/grade-array.sbatch | VL_OUT=$tmp/submitted VL_TASKS=2 VL_GRADER_ARGS=--weaker-sandbox" "$tmp/sbatch.log" &&
     grep -q "call 2: --parsable --dependency=afterany:4101 --chdir=$tmp/submitted --export=ALL --partition=teach $slurm/collect.sbatch" "$tmp/sbatch.log" &&
     grep -q "grading 4 submission(s) of 02 in 2 array task(s): job 4101; collecting in job 4102" "$tmp/submit.log"; then
    ok "submit sends the array (0-1) and then the collect job that waits for it"
  else bad "submit's sbatch calls:"; cat "$tmp/sbatch.log" "$tmp/submit.log"; fi
else bad "submit failed:"; cat "$tmp/submit.log"; fi

# sbatch itself, where installed: it must accept every #SBATCH line of both scripts.
if command -v sbatch >/dev/null; then
  cat >"$tmp/slurm.conf" <<'EOF'
ClusterName=vltest
SlurmctldHost=localhost
AuthType=auth/none
CredType=cred/none
NodeName=localhost CPUs=2 State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
  printf '#!/bin/bash\n#SBATCH --no-such-option=1\ntrue\n' >"$tmp/bogus.sbatch"
  check() {  # FILE [OPTIONS]: sbatch --test-only parses it; 0 when it accepted the directives
    local f=$1; shift
    SLURM_CONF=$tmp/slurm.conf timeout 60 sbatch --test-only "$@" "$f" >"$tmp/sbatch-check.log" 2>&1
    local rc=$?
    [ $rc -eq 0 ] || grep -q "Unable to contact slurm controller" "$tmp/sbatch-check.log"
  }
  if check "$tmp/bogus.sbatch"; then bad "sbatch --test-only accepted an unknown directive: the check cannot fail"
  elif check "$slurm/grade-array.sbatch" --array=0-3 && check "$slurm/collect.sbatch"; then
    ok "sbatch --test-only accepts the directives of grade-array.sbatch and collect.sbatch (no controller: not run)"
  else bad "sbatch --test-only refuses a script:"; cat "$tmp/sbatch-check.log"; fi
else
  echo "not checked: sbatch is not installed (Debian: slurm-client), so sbatch --test-only was not run"
fi

[ $fail -eq 0 ] && echo "the Slurm job array: all as expected"
exit $fail
