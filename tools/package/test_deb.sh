#!/usr/bin/env bash
# Builds the deepnav .deb and installs it into a clean Debian 12 chroot made by mmdebstrap (apt variant,
# plus systemd for `systemd-analyze`), then checks it there:
#   apt installs it with its dependencies; /usr/bin/deepnav runs; the default board /etc/deepnav/board.yaml
#   parses; `deepnav run --validate` names the missing replay recording; with a dive copied in, a 3 s
#   `deepnav run` of the default board exits 0; `systemd-analyze verify` of the installed unit is clean.
# Usage: tools/package/test_deb.sh [DIVE.mcap]   (needs root and a Debian mirror; not part of CI:
# it downloads about 150 MB; see board/service/README.md for the measured time)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${BUILD_DIR:-$root/build-package}"
dive="${1:-}"
mirror="${DEBIAN_MIRROR:-http://deb.debian.org/debian}"

for p in mmdebstrap; do
  command -v "$p" >/dev/null || { echo "test_deb: installing $p"; apt-get install -y -q --no-install-recommends "$p"; }
done

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DDEEPNAV_BUILD_TESTS=OFF \
  -DDEEPNAV_BUILD_BENCH=OFF -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache >/dev/null
ninja -C "$build" -j"${JOBS:-1}" deepnav
rm -f "$build"/deepnav_*.deb
(cd "$build" && cpack -G DEB >/dev/null)
deb="$(ls "$build"/deepnav_*.deb)"
echo "test_deb: built $deb"
dpkg-deb --info "$deb" | sed -n '/Package:/,$p'
dpkg-deb --contents "$deb" | awk '{print "  " $6}'

chroot_dir="$(mktemp -d /tmp/deepnav-chroot.XXXXXX)"
trap 'rm -rf "$chroot_dir"' EXIT
hooks=(
  --customize-hook="copy-in $deb /tmp"
  --customize-hook="chroot \"\$1\" apt-get install -y -q /tmp/$(basename "$deb")"
  --customize-hook='chroot "$1" dpkg -s deepnav | grep -q "Status: install ok installed"'
  --customize-hook='chroot "$1" deepnav --help >/dev/null'
  --customize-hook='chroot "$1" deepnav config /etc/deepnav/board.yaml'
  --customize-hook='chroot "$1" sh -c "! deepnav run --board /etc/deepnav/board.yaml --validate 2>/tmp/v.err; grep -q \"sources.replay_path: recording /var/lib/deepnav/dive.mcap not found\" /tmp/v.err && cat /tmp/v.err"'
  --customize-hook='chroot "$1" sh -c "systemd-analyze verify /usr/lib/systemd/system/deepnav.service 2>/tmp/u.err; test ! -s /tmp/u.err" || { cat "$1/tmp/u.err"; false; }'
)
if [ -n "$dive" ]; then
  hooks+=(
    --customize-hook="mkdir -p \"\$1/var/lib/deepnav\" && cp $dive \"\$1/var/lib/deepnav/dive.mcap\""
    --customize-hook='chroot "$1" sh -c "cd /var/lib/deepnav && deepnav run --board /etc/deepnav/board.yaml --duration 3"'
    --customize-hook='chroot "$1" sh -c "ls -l /var/lib/deepnav/recordings/*.mcap"'
  )
fi
start=$(date +%s)
mmdebstrap --variant=apt --include=systemd --skip=cleanup/apt --quiet "${hooks[@]}" bookworm "$chroot_dir" "$mirror"
echo "test_deb: PASS: installed and ran in a clean Debian 12 chroot ($(( $(date +%s) - start )) s)"
