#!/usr/bin/env bash
# Deploys the robot's firmware and duet-bridge to an STM32MP15 board over ssh (docs/BOARD.md, "Deployment"): copies
# the Cortex-M4 firmware to /lib/firmware, the bridge to /usr/local/bin, the dashboard to /usr/local/share/duet/web and
# the bridge's systemd unit to /etc/systemd/system; loads the firmware through remoteproc's sysfs files (stop, firmware,
# start); waits for the firmware's RPMsg ttys (/dev/ttyRPMSG0 and 1); starts the bridge and checks that it runs.
# None of it has run on a board yet: tests/deploy/deploy_test.sh runs it against a fake board.
#
# Usage: scripts/deploy-stm32mp15.sh [--board USER@HOST] [--firmware ELF] [--bridge PROGRAM] [--web DIR]
#                                    [--ssh-option OPT]... [--wait SECONDS] [--dry-run]
#
# Three ssh connections: a check of the board, the files as one tar stream, and the board's part (the script in
# board_script below, sent to bash on ssh's standard input). DUET_SSH replaces the ssh command (the test's fake board
# sets it); on the board's side DUET_DEPLOY_ROOT prefixes every path, empty on a real board (ssh does not pass it).
set -Eeuo pipefail

source_dir=$(cd "$(dirname "$0")/.." && pwd)
program=deploy-stm32mp15

usage() {
  cat <<EOF
Usage: scripts/deploy-stm32mp15.sh [options]

Copies the Cortex-M4 firmware, duet-bridge, the dashboard and the bridge's systemd unit to an STM32MP15 board over
ssh, loads the firmware through remoteproc, waits for /dev/ttyRPMSG0 and 1, and starts the bridge.

  --board USER@HOST   the board (default root@192.168.7.1: OpenSTLinux's address on the USB OTG port's network)
  --firmware ELF      the Cortex-M4 image
                      (default build/m4-stm32mp15/apps/balbot/balbot-stm32mp15.elf)
  --bridge PROGRAM    duet-bridge for the Cortex-A7 (default build/a7-linux/src/bridge/duet-bridge)
  --web DIR           the dashboard's files (default web/dist)
  --ssh-option OPT    passed to ssh as -o OPT (repeatable), e.g. --ssh-option Port=2222
  --wait SECONDS      how long the firmware has to bring up its ttys (default 5)
  --dry-run           check the local files, then print what would run instead of running it
  --help              this text

Environment: DUET_SSH replaces the ssh command (default ssh). The board needs bash, tar and systemd.
Exit codes: 0 deployed, 1 a step failed (the message names it), 2 wrong command line.
EOF
}

usage_error() {
  echo "$program: $1" >&2
  usage >&2
  exit 2
}

board=root@192.168.7.1
firmware=$source_dir/build/m4-stm32mp15/apps/balbot/balbot-stm32mp15.elf
bridge=$source_dir/build/a7-linux/src/bridge/duet-bridge
web=$source_dir/web/dist
unit=$source_dir/deploy/duet-bridge.service
ssh_options=()
wait_seconds=5
dry_run=
while (($#)); do
  case $1 in
    --board | --firmware | --bridge | --web | --ssh-option | --wait)
      (($# >= 2)) || usage_error "$1 needs a value"
      case $1 in
        --board) board=$2 ;;
        --firmware) firmware=$2 ;;
        --bridge) bridge=$2 ;;
        --web) web=$2 ;;
        --ssh-option) ssh_options+=(-o "$2") ;;
        --wait) wait_seconds=$2 ;;
      esac
      shift 2
      ;;
    --dry-run) dry_run=yes && shift ;;
    --help | -h) usage && exit 0 ;;
    *) usage_error "unknown option '$1'" ;;
  esac
done
[[ -n $board ]] || usage_error "--board needs a value"
[[ $wait_seconds =~ ^[1-9][0-9]*$ ]] || usage_error "--wait takes a whole number of seconds, not '$wait_seconds'"

# The options come before ours: ssh keeps the first value it gets for an option.
read -r -a ssh <<<"${DUET_SSH:-ssh}"
ssh+=("${ssh_options[@]}" -o ConnectTimeout=10 "$board")

current_step=
step() {
  current_step=$1
  echo "== $1"
}
fail() {
  echo "$program: $current_step: $1" >&2
  exit 1
}
trap 'echo "$program: $current_step: failed (the message above says why)" >&2' ERR

# The board's part. It runs in two modes: `check` (is this an STM32MP15 we can deploy to? then a staging folder for
# the files, printed as staging=PATH) and `install STAGING FIRMWARE_NAME WAIT_SECONDS` (everything after the copy).
# It reads nothing from standard input, which is the script itself.
board_script=$(
  cat <<'BOARD'
set -Eeuo pipefail
root=${DUET_DEPLOY_ROOT:-}
rproc=$root/sys/class/remoteproc/remoteproc0
trace=$root/sys/kernel/debug/remoteproc/remoteproc0/trace0
ttys=("$root/dev/ttyRPMSG0" "$root/dev/ttyRPMSG1")
current_step=

step() {
  current_step=$1
  echo "== (board) $1"
}
fail() {
  echo "deploy-stm32mp15: (board) $current_step: $1" >&2
  exit 1
}
trap 'echo "deploy-stm32mp15: (board) $current_step: failed (the message above says why)" >&2' ERR
m4_state() {
  local state=
  [[ -r $rproc/state ]] && state=$(<"$rproc/state")
  echo "${state:-unreadable}"
}
m4_is() {
  [[ $(m4_state) == "$1" ]]
}
# Polls CONDITION every 0.1 s, at most TENTHS times.
wait_until() {
  local tenths=$1
  shift
  until "$@"; do
    ((tenths-- > 0)) || return 1
    sleep 0.1
  done
}
# Running with both ttys, or crashed (no point waiting longer).
firmware_settled() {
  m4_is crashed || { m4_is running && [[ -e ${ttys[0]} && -e ${ttys[1]} ]]; }
}
# What the M4 and the kernel said, for a failed start.
show_m4() {
  local tty
  echo "remoteproc0 state: $(m4_state)" >&2
  for tty in "${ttys[@]}"; do
    if [[ -e $tty ]]; then echo "${tty#"$root"}: present" >&2; else echo "${tty#"$root"}: missing" >&2; fi
  done
  if [[ -r $trace ]]; then
    echo "the firmware's trace buffer (${trace#"$root"}), last lines:" >&2
    tail -n 20 "$trace" >&2 || true
  else
    echo "no trace buffer at ${trace#"$root"} (is debugfs mounted? mount -t debugfs none /sys/kernel/debug)" >&2
  fi
  echo "the kernel's remoteproc and rpmsg messages, last lines:" >&2
  { dmesg 2>/dev/null || true; } | grep -i -E 'remoteproc|rpmsg' | tail -n 10 >&2 || true
}

check_board() {
  current_step=check
  [[ -d $rproc ]] ||
    fail "there is no /sys/class/remoteproc/remoteproc0: is this an STM32MP15 with remoteproc (OpenSTLinux)?"
  [[ -w $rproc/state && -w $rproc/firmware ]] ||
    fail "cannot write remoteproc0's state and firmware files: log in as root (--board root@HOST)"
  local tool
  for tool in tar systemctl; do
    command -v "$tool" >/dev/null || fail "the board has no $tool"
  done
  mkdir -p "$root/tmp"
  echo "staging=$(mktemp -d "$root/tmp/duet-deploy.XXXXXX")"
}

# Replaces FILE by SOURCE in one rename, so a program that runs it keeps the old one until it exits.
replace_file() {
  local source=$1 file=$2 mode=$3
  mkdir -p "$(dirname "$file")"
  cp "$source" "$file.new"
  chmod "$mode" "$file.new"
  mv -f "$file.new" "$file"
}

install_files() {
  local staging=$1 firmware=$2 web=$root/usr/local/share/duet/web
  replace_file "$staging/lib/firmware/$firmware" "$root/lib/firmware/$firmware" 0644
  replace_file "$staging/usr/local/bin/duet-bridge" "$root/usr/local/bin/duet-bridge" 0755
  replace_file "$staging/etc/systemd/system/duet-bridge.service" "$root/etc/systemd/system/duet-bridge.service" 0644
  # The whole folder: the front end's files of the last build, none of an older one.
  mkdir -p "$(dirname "$web")"
  rm -rf "$web.new"
  cp -R "$staging/usr/local/share/duet/web" "$web.new"
  chmod -R u=rwX,go=rX "$web.new"
  rm -rf "$web"
  mv "$web.new" "$web"
  echo "/lib/firmware/$firmware, /usr/local/bin/duet-bridge, /usr/local/share/duet/web," \
    "/etc/systemd/system/duet-bridge.service"
}

deploy() {
  staging=$1
  local firmware=$2 wait_seconds=$3
  trap 'rm -rf "$staging"' EXIT

  # First, so that nothing holds the ttys while the M4 restarts; stopping a unit that is not there fails harmlessly.
  step "stop the bridge"
  systemctl stop duet-bridge 2>/dev/null || true
  ! systemctl is-active --quiet duet-bridge || fail "duet-bridge is still active after systemctl stop duet-bridge"

  step "install the files"
  install_files "$staging" "$firmware"

  # remoteproc takes a new firmware name only while the core is offline. Stopping runs the firmware's shutdown
  # handling (IPCC channel 2), which puts its outputs in the safe state.
  step "stop the Cortex-M4 (remoteproc0 is $(m4_state))"
  if ! m4_is offline; then
    echo stop >"$rproc/state" || fail "remoteproc0 refused stop (a crashed core may need a reboot)"
    wait_until 20 m4_is offline ||
      fail "remoteproc0 is $(m4_state) after stop, not offline (a crashed core may need a reboot)"
  fi

  step "load $firmware and start the Cortex-M4"
  echo "$firmware" >"$rproc/firmware" || fail "remoteproc0 refused the firmware name $firmware"
  if ! echo start >"$rproc/state"; then
    show_m4
    fail "remoteproc0 refused to start $firmware (the kernel's messages above say why)"
  fi

  # The firmware announces its ttys once Linux's rpmsg driver has set the vdev up: shortly after the start.
  step "wait for /dev/ttyRPMSG0 and /dev/ttyRPMSG1 (at most $wait_seconds s)"
  wait_until $((wait_seconds * 10)) firmware_settled || true
  if ! m4_is running || [[ ! -e ${ttys[0]} || ! -e ${ttys[1]} ]]; then
    show_m4
    fail "the firmware did not bring up both RPMsg ttys within $wait_seconds s"
  fi

  step "start the bridge"
  systemctl daemon-reload || fail "systemctl daemon-reload failed"
  systemctl enable --now duet-bridge || fail "systemctl enable --now duet-bridge failed"

  # A bridge that cannot start exits at once and systemd restarts it a second later: still active after a second
  # means it came up.
  step "check that the bridge runs"
  sleep 1
  if ! systemctl is-active --quiet duet-bridge; then
    systemctl status duet-bridge --no-pager --lines 20 >&2 || true
    fail "duet-bridge is not active (journalctl -u duet-bridge has its log)"
  fi
  echo "duet-bridge is active"
}

main() {
  case ${1:-} in
    check) check_board ;;
    install) deploy "$2" "$3" "$4" ;;
    *) fail "unknown mode '${1:-}'" ;;
  esac
}
main "$@" </dev/null
BOARD
)

# True on a real run; on a dry run prints the command line instead and is false.
real_run() {
  if [[ -n $dry_run ]]; then
    printf '  (dry run)'
    printf ' %q' "$@"
    echo
    return 1
  fi
}

# FILE WHAT BUILD: a file for the board, an ARM ELF file (ELF magic, e_machine 40 at offset 18).
check_arm_elf() {
  [[ -f $1 ]] || fail "$2 $1 does not exist: build it ($3) or pass its path"
  local magic machine
  magic=$(head -c 4 "$1" | od -An -c | tr -d ' \n')
  machine=$(od -An -tu2 -j18 -N2 "$1" | tr -d ' \n')
  [[ $magic == 177ELF && $machine == 40 ]] ||
    fail "$2 $1 is not an ARM ELF file (e_machine ${machine:-none}, ARM is 40): is it another preset's build?"
  echo "  $2: $1 ($(wc -c <"$1") bytes)"
}

step "check the local files"
check_arm_elf "$firmware" "the firmware" "cmake --workflow --preset m4-stm32mp15"
check_arm_elf "$bridge" "the bridge" "cmake --workflow --preset a7-linux"
[[ -f $web/index.html ]] ||
  fail "the dashboard's files are not in $web (no index.html): build them (cd web && npm ci && npm run build)"
echo "  the dashboard: $web"
[[ -f $unit ]] || fail "the bridge's unit $unit is missing"
echo "  the bridge's unit: $unit"
firmware_name=$(basename "$firmware")
[[ $firmware_name =~ ^[A-Za-z0-9._-]+$ ]] ||
  fail "the firmware's file name '$firmware_name' is not a plain name (letters, digits, . _ -) for remoteproc"

step "check the board $board (remoteproc0, tar, systemd)"
staging=/tmp/duet-deploy.XXXXXX
if real_run "${ssh[@]}" bash -s -- check; then
  status=0
  check_output=$("${ssh[@]}" bash -s -- check <<<"$board_script") || status=$?
  case $status in
    0) ;;
    255) fail "cannot reach $board over ssh (is the board up and on the network? ssh $board must work)" ;;
    127) fail "the board has no bash" ;;
    *) fail "the board is not ready for duet (the message above says why)" ;;
  esac
  staging=$(sed -n 's/^staging=//p' <<<"$check_output")
  [[ $staging == */tmp/duet-deploy.* ]] || fail "the board did not make a staging folder (it said: $check_output)"
fi

step "copy the firmware, the bridge, the dashboard and the unit to $board:$staging"
local_staging=$(mktemp -d)
trap 'rm -rf "$local_staging"' EXIT
mkdir -p "$local_staging/lib/firmware" "$local_staging/usr/local/bin" "$local_staging/usr/local/share/duet" \
  "$local_staging/etc/systemd/system"
cp "$firmware" "$local_staging/lib/firmware/$firmware_name"
cp "$bridge" "$local_staging/usr/local/bin/duet-bridge"
cp -RL "$web" "$local_staging/usr/local/share/duet/web"
cp "$unit" "$local_staging/etc/systemd/system/duet-bridge.service"
if [[ -n $dry_run ]]; then
  echo "  (dry run) tar -C $local_staging -cf - . | ${ssh[*]} tar -xf - -C $staging"
else
  tar -C "$local_staging" --owner=0 --group=0 -cf - . | "${ssh[@]}" tar -xf - -C "$(printf %q "$staging")" ||
    fail "copying to $board:$staging failed"
fi

step "on the board: stop the bridge, install, load the firmware, wait for its ttys, start the bridge"
if real_run "${ssh[@]}" bash -s -- install "$staging" "$firmware_name" "$wait_seconds"; then
  status=0
  "${ssh[@]}" bash -s -- install "$(printf %q "$staging")" "$firmware_name" "$wait_seconds" <<<"$board_script" ||
    status=$?
  case $status in
    0) ;;
    255) fail "lost the ssh connection to $board" ;;
    *) fail "a step on the board failed (the message above says which)" ;;
  esac
else
  echo "  with this script on its standard input:"
  mapfile -t board_script_lines <<<"$board_script"
  printf '    %s\n' "${board_script_lines[@]}"
  exit 0
fi

# ssh's options again for the tunnel, as this script's caller gave them.
tunnel=(ssh "${ssh_options[@]}" -N -L 5555:127.0.0.1:5555 -L 8765:127.0.0.1:8765 "$board")
cat <<EOF

$program: done. The firmware runs on the Cortex-M4 and duet-bridge on Linux, listening on the board's localhost.
From this PC, keep a tunnel open:
  ${tunnel[*]}
then
  duet xcp info --connect tcp://127.0.0.1:5555
  duet monitor --xcp tcp://127.0.0.1:5555 --a2l apps/balbot/generated/balbot.a2l   # dashboard over XCP, port 8766
  http://127.0.0.1:8765/   the bridge's dashboard
On the board: systemctl status duet-bridge, journalctl -u duet-bridge, cat /sys/class/remoteproc/remoteproc0/state
EOF
