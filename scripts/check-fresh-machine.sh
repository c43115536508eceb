#!/usr/bin/env bash
# Checks the README's promise on a fresh Debian 12: makes a minimal Debian 12 in a folder (debootstrap), clones this
# repository into it, and runs the README's test command (or the command given) there as root, in a chroot.
# Needs root and Debian's package mirror. Takes a few minutes; not part of CI.
#
# Usage: scripts/check-fresh-machine.sh [command, default: scripts/test.sh]
set -euo pipefail
cd "$(dirname "$0")/.."
command=${1:-scripts/test.sh}

((EUID == 0)) || { echo "check-fresh-machine: run as root (debootstrap and chroot need it)" >&2; exit 1; }
command -v debootstrap >/dev/null || apt-get install -y -q debootstrap

root=$(mktemp -d /tmp/duet-fresh.XXXXXX)
cleanup() {
  for mount in dev sys proc; do umount -R "$root/$mount" 2>/dev/null || true; done
  rm -rf --one-file-system "$root"
}
trap cleanup EXIT

echo "check-fresh-machine: making a minimal Debian 12 in $root"
debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian >"$root.debootstrap.log" 2>&1 ||
  { cat "$root.debootstrap.log"; exit 1; }
rm -f "$root.debootstrap.log"
cp /etc/resolv.conf "$root/etc/resolv.conf"
mount -t proc proc "$root/proc"
mount -t sysfs sys "$root/sys"
mount --rbind /dev "$root/dev"
git clone -q "$PWD" "$root/root/duet"

echo "check-fresh-machine: running '$command' in a clone there"
chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  /bin/bash -c "cd /root/duet && $command"
echo "check-fresh-machine: '$command' passed on a fresh Debian 12"
