#!/usr/bin/env bash
# One test of sandbox-run: runs a hostile program (hostile.cpp) inside the sandbox with one
# mechanism and checks that the sandbox held. Exit 0 = held, 1 = broken, 77 = skipped (the
# mechanism is not available here, or the property does not apply; the reason is printed).
#
#   sandbox_test.sh SANDBOX_RUN HOSTILE MODE CASE UID
set -uo pipefail
sandbox=$1 hostile=$2 mode=$3 case_name=$4 uid=$5
SKIP=77

fail() { echo "FAIL ($mode, $case_name): $*"; show; exit 1; }
skip() { echo "SKIPPED ($mode, $case_name): $*"; exit "$SKIP"; }
show() {
  echo "--- stdout"; cat "$base/out" 2>/dev/null
  echo "--- stderr"; cat "$base/err" 2>/dev/null
  echo "--- status"; cat "$base/results/status" 2>/dev/null
}

is_root=0
[ "$(id -u)" -eq 0 ] && is_root=1
[ "$is_root" = 1 ] || uid=$(id -u)

base=$(mktemp -d /tmp/sandbox-test.XXXXXX)
chmod 0755 "$base"                      # the sandbox uid may pass through, as to any workdir
mkdir "$base/work" "$base/public"
echo "a public scene" >"$base/public/scene.txt"
mkdir -m 0700 "$base/secret" "$base/results"   # as the grader keeps expected images and results
echo "an expected image" >"$base/secret/expected.png"
cp "$hostile" "$base/work/hostile"
chmod 0755 "$base/work/hostile"
listener=""
cleanup() {
  [ -z "$listener" ] || kill "$listener" 2>/dev/null
  rm -rf -- "$base"
}
trap cleanup EXIT

# sandbox [sandbox-run options] -- command...: stdout, stderr and the status file in $base.
rc=0
sandbox() {
  rm -f "$base/results/status"
  rc=0
  "$sandbox" --mode "$mode" --uid "$uid" --workdir "${work:-$base/work}" --ro "$base/public" \
    --status "$base/results/status" "$@" >"$base/out" 2>"$base/err" </dev/null || rc=$?
}
status_of() { sed -n "s/^$1=//p" "$base/results/status"; }
# expect RESULT EXIT: the status file, the exit status and the last line on stderr all agree.
expect() {
  [ -f "$base/results/status" ] || fail "no status file"
  [ "$(status_of result)" = "$1" ] || fail "result is '$(status_of result)', expected '$1'"
  [ "$(status_of exit)" = "$2" ] || fail "exit is '$(status_of exit)', expected '$2'"
  [ "$rc" = "$2" ] || fail "sandbox-run exited with $rc, expected $2"
  tail -n 1 "$base/err" | grep -q "^sandbox-run: result=$1 exit=$2 " ||
    fail "the last line on stderr is not sandbox-run's result line"
}
output_has() { grep -q -- "$1" "$base/out" || fail "stdout lacks '$1'"; }
# No process of the sandbox uid is left (zombies already dead, waiting to be reaped, aside).
none_left() {
  local live
  if [ "$is_root" = 1 ]; then
    live=$(ps -U "$uid" -o pid=,stat=,args= | awk '$2 !~ /^Z/' || true)
    [ -z "$live" ] || fail "processes of uid $uid survive: $live"
  fi
}
wall_ms() { status_of wall_ms; }

# The mechanism must exist here, or the test is skipped with the reason.
"$sandbox" --mode "$mode" --uid "$uid" --workdir "$base/work" -- true >/dev/null 2>"$base/err" ||
  skip "$(grep -m1 error "$base/err")"
mechanism=$(sed -n 's/^sandbox-run: mechanism=\([a-z]*\).*/\1/p' "$base/err")
# Without root there is no separate uid: hiding by permissions cannot hide the caller's files.
fs_hidden=1
[ "$mechanism" = bwrap ] || [ "$is_root" = 1 ] || fs_hidden=0

case "$case_name" in
  timeout)  # an endless loop that ignores SIGTERM is killed at the deadline
    sandbox --time 0.3 --grace 0.2 -- ./hostile spin
    expect timeout 124
    [ "$(wall_ms)" -lt 5000 ] || fail "took $(wall_ms) ms for a 0.3 s limit"
    none_left
    ;;
  orphans)  # children that leave the session, ignore SIGTERM and outlive the command
    marker="sandbox-orphan-$$-$RANDOM"
    sandbox --time 5 -- ./hostile orphans "$marker" 4
    expect exited 0
    output_has "started 4 orphans"
    survivors=$(pgrep -a -f "$marker" || true)
    [ -z "$survivors" ] || fail "orphans survive: $survivors"
    none_left
    ;;
  procs)  # a fork loop stops at the process limit, and none of its children survive
    sandbox --procs 16 -- ./hostile forkmany 200
    expect exited 3
    forked=$(sed -n 's/^forked //p' "$base/out")
    [ -n "$forked" ] && [ "$forked" -lt 16 ] || fail "forked '$forked' children with --procs 16"
    none_left
    ;;
  memory)  # a 3 GB allocation fails inside the limit
    sandbox --mem 256 -- ./hostile alloc 3072
    expect exited 3
    output_has "refused: malloc"
    none_left
    ;;
  fsize)  # a huge file is stopped at the file-size limit (SIGXFSZ: 128+25)
    sandbox --fsize 1 -- ./hostile writefile big.bin 100
    expect exited 153
    size=$(stat -c %s "$base/work/big.bin")
    [ "$size" -le 1048576 ] || fail "big.bin has $size bytes with --fsize 1"
    ;;
  nofile)  # descriptors stop at the limit
    sandbox --nofile 32 -- ./hostile openmany 1000
    expect exited 3
    opened=$(sed -n 's/^opened //p' "$base/out")
    [ -n "$opened" ] && [ "$opened" -lt 32 ] || fail "opened '$opened' descriptors with --nofile 32"
    ;;
  cpu)  # CPU time stops at the limit (SIGXCPU: 128+24), well before the wall-time limit
    sandbox --cpu 1 --time 20 -- ./hostile burn
    expect exited 152
    none_left
    ;;
  network)  # no connection to a server listening on the host's 127.0.0.1
    [ "$mechanism" != plain ] || skip "the plain mechanism has no network namespace (see README.md)"
    "$hostile" listen "$base/port" 20 >/dev/null 2>&1 &
    listener=$!
    for _ in $(seq 1 100); do [ -s "$base/port" ] && break; sleep 0.02; done
    port=$(cat "$base/port" 2>/dev/null) || fail "the test's listener did not start"
    "$hostile" connect "$port" >/dev/null || fail "the test's listener is not reachable from outside"
    sandbox -- ./hostile connect "$port"
    expect exited 3
    output_has "refused: connect"
    ;;
  read)  # a directory that is not given is absent (bwrap) or unreadable (permissions)
    [ "$fs_hidden" = 1 ] || skip "not root and no bwrap: the caller's own files cannot be hidden"
    sandbox -- ./hostile read "$base/public/scene.txt"
    expect exited 0
    output_has "a public scene"
    sandbox -- ./hostile read "$base/secret/expected.png"
    expect exited 3
    if [ "$mechanism" = bwrap ]; then
      output_has "No such file or directory"
    else
      output_has "Permission denied"
    fi
    ;;
  write)  # the workdir is the only writable place; nothing is left in /tmp
    [ "$fs_hidden" = 1 ] || skip "not root and no bwrap: the caller's own files stay writable"
    leftover=/tmp/sandbox-leftover-$uid-$$
    sandbox -- ./hostile write "$base/work/result.txt" "$leftover"
    expect exited 0
    [ -f "$base/work/result.txt" ] || fail "a file written in the workdir is not there"
    [ ! -e "$leftover" ] || { rm -f "$leftover"; fail "$leftover is left behind"; }
    sandbox -- ./hostile write "$base/public/planted.png" "$base/planted.png" \
      "$base/secret/expected.png" /etc/sandbox-planted
    expect exited 3
    [ "$(grep -c '^refused: ' "$base/out")" = 4 ] || fail "not every write was refused"
    [ "$(cat "$base/secret/expected.png")" = "an expected image" ] || fail "the secret was changed"
    [ ! -e "$base/public/planted.png" ] && [ ! -e "$base/planted.png" ] || fail "a file was planted"
    # A later command of the same uid, in another workdir, cannot reach this workdir's files.
    mkdir "$base/work2" && cp "$base/work/hostile" "$base/work2/"
    work=$base/work2 sandbox -- ./hostile write "$base/work/result.txt"
    expect exited 3
    [ "$(cat "$base/work/result.txt")" = "written by the sandboxed command" ] ||
      fail "an earlier workdir was changed by a later command"
    ;;
  fake)  # exit(0) with fake output: the caller sees exactly that; a fake result line and a
         # rewritten status file do not change the real result
    sandbox -- ./hostile fake 0
    expect exited 0
    sandbox -- ./hostile fake 7 "$base/results/status"
    expect exited 7
    output_has "refused: status file"
    sandbox -- sh -c 'echo "sandbox-run: result=timeout exit=124" >&2; exit 124'
    expect exited 124
    ;;
  reaped)  # under a PID 1 that never reaps (a container's), killed orphans leave no zombie
    [ "$is_root" = 1 ] || skip "needs root (the sweep kills as the sandbox uid)"
    unshare --pid --fork --mount-proc true 2>/dev/null || skip "no PID namespace here to play a non-reaping PID 1"
    marker="sandbox-reaped-$$-$RANDOM"
    # In a PID namespace whose PID 1 is `sleep` (never waits): orphans would become its zombies.
    unshare --pid --fork --kill-child --mount-proc sh -c '
      ( "$1" --mode "$2" --uid "$3" --workdir "$4" --time 5 -- ./hostile orphans "$5" 4 >"$6/out" 2>"$6/err"
        sleep 0.3
        ps -U "$3" -o pid=,stat=,comm= >"$6/left" ) &
      exec sleep 15' reaper "$sandbox" "$mode" "$uid" "$base/work" "$marker" "$base" &
    ns=$!
    for _ in $(seq 150); do [ -f "$base/left" ] && break; sleep 0.1; done
    kill "$ns" 2>/dev/null; wait "$ns" 2>/dev/null
    [ -f "$base/left" ] || fail "the sandbox did not finish under the non-reaping PID 1"
    grep -q "started 4 orphans" "$base/out" || fail "the hostile program did not start its orphans"
    [ ! -s "$base/left" ] || fail "processes (zombies) of uid $uid are left: $(tr '\n' ' ' <"$base/left")"
    ;;
  nonroot)  # started by an ordinary user: says so, and still kills, limits and reports
    [ "$is_root" = 1 ] || skip "needs root to start sandbox-run as another user"
    chown "$uid:$uid" "$base/work"
    mkdir -m 0700 "$base/own" && chown "$uid:$uid" "$base/own"
    # A copy the ordinary user can reach: the repository may sit in a folder only root can
    # enter (a clone in `mktemp -d`, mode 0700).
    cp "$sandbox" "$base/sandbox-run" && chmod 755 "$base/sandbox-run"
    as_user() {
      rc=0
      setpriv --reuid="$uid" --regid="$uid" --clear-groups -- "$base/sandbox-run" --mode "$mode" \
        --workdir "$base/work" --status "$base/own/status" "$@" >"$base/out" 2>"$base/err" || rc=$?
      cp "$base/own/status" "$base/results/status" 2>/dev/null || rm -f "$base/results/status"
    }
    as_user -- ./hostile fake 5
    expect exited 5
    grep -q "^sandbox-run: mechanism=.* (not root" "$base/err" || fail "does not say it is not root"
    marker="sandbox-orphan-$$-$RANDOM"
    as_user --time 0.5 --grace 0.3 -- ./hostile orphans "$marker" 2
    expect exited 0
    as_user --time 0.5 --grace 0.3 -- ./hostile spin
    expect timeout 124
    if [ "$(sed -n 's/^sandbox-run: mechanism=\([a-z]*\).*/\1/p' "$base/err")" != plain ]; then
      survivors=$(pgrep -a -f "$marker" || true)
      [ -z "$survivors" ] || fail "orphans survive: $survivors"
    else
      pkill -KILL -f "$marker"  # documented: without root and namespaces, setsid() escapes
    fi
    ;;
  *)
    echo "unknown case $case_name"; exit 2 ;;
esac
echo "ok ($mechanism, $case_name)"
