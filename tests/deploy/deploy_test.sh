#!/usr/bin/env bash
# scripts/deploy-stm32mp15.sh against a fake board, without hardware. The board is a temporary folder used as its root
# (/lib/firmware, /usr/local, /etc/systemd/system, /dev, /tmp, remoteproc0's sysfs files), reached through a fake ssh
# (DUET_SSH) that runs the command here with DUET_DEPLOY_ROOT pointing at that folder and fake systemctl and dmesg
# first on PATH. While a command runs, a fake kernel watches remoteproc0's state file: "start" makes the core running
# and then the two RPMsg ttys appear (unless FAKE_NO_TTYS), "stop" takes them away and makes it offline. systemctl
# and the kernel log what happens to the board's `events` file, so the order of the steps can be checked.
#
# Usage: tests/deploy/deploy_test.sh [SOURCE_DIR]     (ctest: deploy_stm32mp15). Prints "N passed, M failed".
set -euo pipefail
source_dir=$(cd "${1:-$(dirname "$0")/../..}" && pwd)
deploy=$source_dir/scripts/deploy-stm32mp15.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/bin" "$work/board-bin" "$work/local/web"

cat >"$work/bin/ssh" <<'EOF'
#!/usr/bin/env bash
# The fake board's ssh: logs its command line, then runs the command here on the fake board.
set -euo pipefail
echo "$*" >>"$FAKE_BOARD_ROOT/ssh.log"
while (($#)) && [[ $1 == -* ]]; do
  case $1 in
    -o) shift 2 ;;
    *) shift ;;
  esac
done
host=$1
shift
if [[ $host == *unreachable* ]]; then
  echo "ssh: connect to host ${host#*@} port 22: No route to host" >&2
  exit 255
fi
"$FAKE_BOARD_BIN/fake-kernel" &
kernel=$!
status=0
DUET_DEPLOY_ROOT=$FAKE_BOARD_ROOT PATH=$FAKE_BOARD_BIN:$PATH bash -c "$*" || status=$?
kill "$kernel" 2>/dev/null || true
wait "$kernel" 2>/dev/null || true
exit "$status"
EOF

cat >"$work/board-bin/fake-kernel" <<'EOF'
#!/usr/bin/env bash
# The fake board's remoteproc0: acts on what is written to its state file, as the kernel does on the write.
set -uo pipefail
root=$FAKE_BOARD_ROOT
rproc=$root/sys/class/remoteproc/remoteproc0
[[ -d $rproc ]] || exit 0
while :; do
  case $(cat "$rproc/state" 2>/dev/null) in
    start)
      echo "remoteproc started $(<"$rproc/firmware")" >>"$root/events"
      echo running >"$rproc/state"
      [[ -n ${FAKE_NO_TTYS:-} ]] || touch "$root/dev/ttyRPMSG0" "$root/dev/ttyRPMSG1"
      ;;
    stop)
      echo "remoteproc stopped" >>"$root/events"
      rm -f "$root/dev/ttyRPMSG0" "$root/dev/ttyRPMSG1"
      echo offline >"$rproc/state"
      ;;
  esac
  sleep 0.02
done
EOF

cat >"$work/board-bin/systemctl" <<'EOF'
#!/usr/bin/env bash
# The fake board's systemd: the bridge is active while run/duet-bridge.active exists.
root=$DUET_DEPLOY_ROOT
active=$root/run/duet-bridge.active
echo "systemctl $*" >>"$root/events"
case "$*" in
  "stop duet-bridge") rm -f "$active" ;;
  "is-active --quiet duet-bridge") [[ -e $active ]] ;;
  daemon-reload) ;;
  "enable --now duet-bridge")
    if [[ ! -f $root/etc/systemd/system/duet-bridge.service ]]; then
      echo "Failed to enable unit: Unit file duet-bridge.service does not exist." >&2
      exit 1
    fi
    [[ -n ${FAKE_BRIDGE_FAILS:-} ]] || { mkdir -p "$root/run" && touch "$active"; }
    ;;
  "status duet-bridge"*) printf '%s\n' "x duet-bridge.service - duet bridge" \
    "     Active: activating (auto-restart) (Result: exit-code)" ;;
  *)
    echo "fake systemctl: unexpected command: $*" >&2
    exit 1
    ;;
esac
EOF

cat >"$work/board-bin/dmesg" <<'EOF'
#!/usr/bin/env bash
echo "[   12.100000] remoteproc remoteproc0: powering up m4"
echo "[   12.110000] usb 2-1: new high-speed USB device"
echo "[   12.120000] remoteproc remoteproc0: remote processor m4 is now up"
EOF
chmod +x "$work/bin/ssh" "$work/board-bin/"*

# The PC's files: ELF headers with e_machine (offset 18) ARM (40) or x86-64 (62), and something to tell them apart.
fake_elf() {
  {
    printf '\177ELF\001\001\001' && head -c 11 /dev/zero
    printf '%b' "\\0$2" && head -c 1 /dev/zero
    echo "$3"
  } >"$1"
}
firmware=$work/local/balbot-stm32mp15.elf
bridge=$work/local/duet-bridge
web=$work/local/web
fake_elf "$firmware" 050 "the robot's firmware"
fake_elf "$bridge" 050 "duet-bridge for armhf"
fake_elf "$work/local/duet-bridge-x86" 076 "duet-bridge for the PC"
echo "<html>dashboard</html>" >"$web/index.html"
echo "// app" >"$web/app.js"

# A board in DIR: remoteproc0 in STATE with FIRMWARE (or none at all), the bridge active or not.
make_board() {
  local board=$1 state=${2:-offline} firmware=${3:-rproc-m4-fw} bridge_active=${4:-}
  mkdir -p "$board"/{dev,tmp,lib/firmware,run} "$board/sys/kernel/debug/remoteproc/remoteproc0"
  : >"$board/events"
  if [[ $state != none ]]; then
    mkdir -p "$board/sys/class/remoteproc/remoteproc0"
    echo "$state" >"$board/sys/class/remoteproc/remoteproc0/state"
    echo "$firmware" >"$board/sys/class/remoteproc/remoteproc0/firmware"
  fi
  printf '%s\n' "[0.000] balbot: started" "[0.001] balbot: waiting for Linux's rpmsg driver" \
    >"$board/sys/kernel/debug/remoteproc/remoteproc0/trace0"
  [[ -z $bridge_active ]] || touch "$board/run/duet-bridge.active"
}

# Runs the deploy script against the board in DIR with the PC's files and ARGS; sets status, elapsed and output.
run_deploy() {
  local board=$1
  shift
  local start=$SECONDS
  output=$board.out
  status=0
  FAKE_BOARD_ROOT=$board FAKE_BOARD_BIN=$work/board-bin DUET_SSH=$work/bin/ssh \
    "$deploy" --firmware "$firmware" --bridge "$bridge" --web "$web" "$@" >"$output" 2>&1 || status=$?
  elapsed=$((SECONDS - start))
}

passed=0
failed=0
problems=()
expect() {
  local what=$1
  shift
  "$@" || problems+=("$what")
}
finish() {
  if ((${#problems[@]} == 0)); then
    echo "ok   $1"
    passed=$((passed + 1))
  else
    echo "FAIL $1"
    printf '       expected: %s\n' "${problems[@]}"
    echo "       output:"
    sed 's/^/       | /' "$output"
    failed=$((failed + 1))
  fi
  problems=()
}
has() { grep -qF -- "$2" "$1"; }
lacks() { ! grep -qF -- "$2" "$1" 2>/dev/null; }
reads() { [[ -f $1 && $(<"$1") == "$2" ]]; }
# FILE TEXT...: each TEXT on a line after the line of the one before.
in_order() {
  local file=$1 line=0 next text
  shift
  for text; do
    next=$(tail -n +$((line + 1)) "$file" | grep -nF -m1 -- "$text" | cut -d: -f1) || return 1
    line=$((line + next))
  done
}
no_staging_left() { ! compgen -G "$1/tmp/duet-deploy.*" >/dev/null; }

board=$work/good
make_board "$board"
run_deploy "$board"
rproc=$board/sys/class/remoteproc/remoteproc0
expect "exit code 0, was $status" test "$status" -eq 0
expect "the firmware in /lib/firmware" cmp -s "$firmware" "$board/lib/firmware/balbot-stm32mp15.elf"
expect "the bridge in /usr/local/bin" cmp -s "$bridge" "$board/usr/local/bin/duet-bridge"
expect "the bridge executable" test -x "$board/usr/local/bin/duet-bridge"
expect "the dashboard in /usr/local/share/duet/web" \
  cmp -s "$web/index.html" "$board/usr/local/share/duet/web/index.html"
expect "the unit in /etc/systemd/system" \
  cmp -s "$source_dir/deploy/duet-bridge.service" "$board/etc/systemd/system/duet-bridge.service"
expect "the firmware's name written to remoteproc0/firmware" reads "$rproc/firmware" balbot-stm32mp15.elf
expect "remoteproc0 running" reads "$rproc/state" running
expect "the ttys there" test -e "$board/dev/ttyRPMSG0" -a -e "$board/dev/ttyRPMSG1"
expect "the bridge active" test -e "$board/run/duet-bridge.active"
expect "stop bridge, start M4, reload, enable bridge, in that order" in_order "$board/events" \
  "systemctl stop duet-bridge" "remoteproc started balbot-stm32mp15.elf" "systemctl daemon-reload" \
  "systemctl enable --now duet-bridge" "systemctl is-active --quiet duet-bridge"
expect "no stop of an offline M4" lacks "$board/events" "remoteproc stopped"
expect "three ssh connections to root@192.168.7.1 (the default)" \
  test "$(grep -c 'root@192.168.7.1' "$board/ssh.log")" -eq 3
expect "no staging folder left on the board" no_staging_left "$board"
expect "each step announced" in_order "$output" "== check the local files" "== check the board" "== copy" \
  "== (board) stop the bridge" "== (board) install the files" "== (board) stop the Cortex-M4" \
  "== (board) load balbot-stm32mp15.elf" "== (board) wait for /dev/ttyRPMSG0" "== (board) start the bridge" \
  "== (board) check that the bridge runs"
expect "the tunnel printed" has "$output" "ssh -N -L 5555:127.0.0.1:5555 -L 8765:127.0.0.1:8765 root@192.168.7.1"
expect "duet xcp info printed" has "$output" "duet xcp info --connect tcp://127.0.0.1:5555"
finish "a good deploy: files in place, firmware loaded, ttys up, bridge enabled"

board=$work/again
make_board "$board" running old-firmware.elf bridge-active
mkdir -p "$board/usr/local/share/duet/web"
echo "// an older build's asset" >"$board/usr/local/share/duet/web/old-asset.js"
run_deploy "$board" --board me@board.local --ssh-option Port=2222
rproc=$board/sys/class/remoteproc/remoteproc0
expect "exit code 0, was $status" test "$status" -eq 0
expect "bridge stopped, then M4 stopped, new firmware started, bridge enabled" in_order "$board/events" \
  "systemctl stop duet-bridge" "remoteproc stopped" "remoteproc started balbot-stm32mp15.elf" \
  "systemctl enable --now duet-bridge"
expect "remoteproc0 running the new firmware" reads "$rproc/state" running
expect "the older dashboard's files gone" test ! -e "$board/usr/local/share/duet/web/old-asset.js"
expect "ssh given the board and the option" has "$board/ssh.log" "-o Port=2222 -o ConnectTimeout=10 me@board.local"
expect "the tunnel with the option" has "$output" "ssh -o Port=2222 -N -L 5555:127.0.0.1:5555"
finish "a deploy over a running firmware and bridge: both stopped first, --board and --ssh-option used"

board=$work/no-remoteproc
make_board "$board" none
run_deploy "$board"
expect "exit code 1, was $status" test "$status" -eq 1
expect "the message" has "$output" "check the board root@192.168.7.1 (remoteproc0, tar, systemd): "
expect "the reason" has "$output" "there is no /sys/class/remoteproc/remoteproc0"
expect "one ssh connection only" test "$(wc -l <"$board/ssh.log")" -eq 1
expect "nothing copied" test ! -e "$board/lib/firmware/balbot-stm32mp15.elf"
finish "a board without remoteproc: fails at the check, copies nothing"

board=$work/no-ttys
make_board "$board"
FAKE_NO_TTYS=1 run_deploy "$board" --wait 1
expect "exit code 1, was $status" test "$status" -eq 1
expect "the step and the reason" \
  has "$output" "wait for /dev/ttyRPMSG0 and /dev/ttyRPMSG1 (at most 1 s): the firmware did not bring up both"
expect "the state shown" has "$output" "remoteproc0 state: running"
expect "the missing tty shown" has "$output" "/dev/ttyRPMSG0: missing"
expect "the trace buffer's tail shown" has "$output" "balbot: waiting for Linux's rpmsg driver"
expect "the kernel's remoteproc messages shown" has "$output" "remoteproc remoteproc0: powering up m4"
expect "no other kernel messages" lacks "$output" "usb 2-1"
expect "the bridge not started" lacks "$board/events" "enable --now"
expect "a bounded wait (took $elapsed s)" test "$elapsed" -le 4
expect "no staging folder left on the board" no_staging_left "$board"
finish "ttys that never appear: fails after the bounded wait, shows the state and the trace"

board=$work/bridge-fails
make_board "$board"
FAKE_BRIDGE_FAILS=1 run_deploy "$board"
expect "exit code 1, was $status" test "$status" -eq 1
expect "the message" has "$output" "check that the bridge runs: duet-bridge is not active"
expect "systemctl status shown" has "$output" "activating (auto-restart)"
finish "a bridge that does not stay up: fails with its status"

board=$work/missing-firmware
make_board "$board"
run_deploy "$board" --firmware "$work/local/missing.elf"
expect "exit code 1, was $status" test "$status" -eq 1
expect "the message" has "$output" "check the local files: the firmware $work/local/missing.elf does not exist"
expect "no ssh connection" test ! -e "$board/ssh.log"
finish "a missing local firmware file: fails before connecting"

board=$work/wrong-bridge
make_board "$board"
run_deploy "$board" --bridge "$work/local/duet-bridge-x86"
expect "exit code 1, was $status" test "$status" -eq 1
expect "the message" has "$output" "duet-bridge-x86 is not an ARM ELF file (e_machine 62"
expect "no ssh connection" test ! -e "$board/ssh.log"
finish "the PC's bridge instead of the armhf one: fails before connecting"

board=$work/unreachable
make_board "$board"
run_deploy "$board" --board root@unreachable
expect "exit code 1, was $status" test "$status" -eq 1
expect "the message" has "$output" "cannot reach root@unreachable over ssh"
finish "an unreachable board: fails at the check"

board=$work/bad-option
make_board "$board"
run_deploy "$board" --frobnicate
expect "exit code 2, was $status" test "$status" -eq 2
expect "the message" has "$output" "unknown option '--frobnicate'"
expect "the usage" has "$output" "Usage: scripts/deploy-stm32mp15.sh"
run_deploy "$board" --wait soon
expect "--wait soon: exit code 2, was $status" test "$status" -eq 2
run_deploy "$board" --board
expect "--board without a value: exit code 2, was $status" test "$status" -eq 2
expect "no ssh connection" test ! -e "$board/ssh.log"
finish "bad options: exit code 2 with the usage"

board=$work/help
make_board "$board"
run_deploy "$board" --help
expect "exit code 0, was $status" test "$status" -eq 0
expect "the usage" has "$output" "--ssh-option OPT"
finish "--help"

board=$work/dry-run
make_board "$board"
run_deploy "$board" --dry-run
expect "exit code 0, was $status" test "$status" -eq 0
expect "the commands shown" in_order "$output" "bash -s -- check" "(dry run) tar" \
  "bash -s -- install" "echo start >\"\$rproc/state\""
expect "no ssh connection" test ! -e "$board/ssh.log"
expect "the board untouched" reads "$board/sys/class/remoteproc/remoteproc0/state" offline
finish "--dry-run: prints the commands and the board's script, runs nothing"

echo "$passed passed, $failed failed"
((failed == 0))
