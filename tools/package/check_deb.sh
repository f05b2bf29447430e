#!/usr/bin/env bash
# Checks a built deepnav .deb without installing it: architecture, Depends, the files a vehicle needs
# (binary of that architecture, systemd unit, default board and panel as conffiles, maintainer scripts),
# then runs the packaged binary on the packaged default board (`deepnav config`), under
# qemu-aarch64-static with the arm64 sysroot for an arm64 package.
# Usage: tools/package/check_deb.sh DEB ARCH [SYSROOT]   (ARCH: amd64 | arm64; SYSROOT for arm64)
set -euo pipefail
deb="$1"
arch="$2"
sysroot="${3:-}"
fail() { echo "check_deb: $deb: $*" >&2; exit 1; }

[ -f "$deb" ] || fail "not found"
[ "$(dpkg-deb -f "$deb" Architecture)" = "$arch" ] || fail "Architecture is '$(dpkg-deb -f "$deb" Architecture)', not $arch"
depends="$(dpkg-deb -f "$deb" Depends)"
for lib in libc6 libstdc++6 libopencv-core406 libyaml-cpp0.7 libaravis-0.8-0 libmodbus5; do
  grep -q "\b$lib\b" <<<"$depends" || fail "Depends lacks $lib (Depends: '$depends')"
done

contents="$(dpkg-deb --contents "$deb" | awk '{print $6}')"
for f in ./usr/bin/deepnav ./usr/lib/systemd/system/deepnav.service ./etc/deepnav/board.yaml \
         ./etc/deepnav/panel.yaml ./usr/share/deepnav/boards/sim/board.yaml \
         ./usr/share/deepnav/boards/example-vehicle/board.yaml ./usr/share/doc/deepnav/README.md; do
  grep -qx "$f" <<<"$contents" || fail "missing $f"
done

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
dpkg-deb --control "$deb" "$work/DEBIAN"
[ "$(sort "$work/DEBIAN/conffiles")" = "$(printf '/etc/deepnav/board.yaml\n/etc/deepnav/panel.yaml')" ] ||
  fail "conffiles are '$(tr '\n' ' ' <"$work/DEBIAN/conffiles")', not the default board and panel"
for script in postinst postrm; do [ -x "$work/DEBIAN/$script" ] || fail "no executable $script"; done

dpkg-deb --extract "$deb" "$work/root"
case "$arch" in
  arm64) pattern="ARM aarch64"; run=(qemu-aarch64-static -L "${sysroot:?arm64 needs the sysroot}") ;;
  amd64) pattern="x86-64"; run=() ;;
  *) fail "unknown architecture $arch" ;;
esac
file -L "$work/root/usr/bin/deepnav" | grep -q "$pattern" || fail "usr/bin/deepnav is not $pattern: $(file -L "$work/root/usr/bin/deepnav")"
out="$("${run[@]}" "$work/root/usr/bin/deepnav" config "$work/root/etc/deepnav/board.yaml" 2>&1)" ||
  fail "the packaged deepnav refused the packaged board: $out"
grep -q "^\[Unit\]" "$work/root/usr/lib/systemd/system/deepnav.service" || fail "deepnav.service has no [Unit] section"
echo "check_deb: $(basename "$deb"): $arch, $(wc -l <<<"$contents") entries, conffiles board.yaml panel.yaml, packaged binary validates the default board"
echo "check_deb: Depends: $depends"
