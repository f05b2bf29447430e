#!/usr/bin/env bash
# deepnav under a real systemd: boots a small Debian 12 system (systemd as PID 1) in a QEMU VM, installs
# the project's .deb there and checks the unit's contract with systemd itself:
#   - `systemctl start deepnav` returns once READY=1 came, and the unit is active (running), with the
#     STATUS= sent alongside READY=1 as its status text;
#   - the periodic STATUS= (stage, health, sensors) shows in `systemctl status deepnav`;
#   - a healthy loop keeps the watchdog fed (no restart over several watchdog periods);
#   - a stalled nav loop (only the nav thread stopped, tools/vm/stall_thread.c) shows `health stalled`
#     in the status, stops feeding the watchdog, and systemd kills (SIGABRT) and restarts the service;
#   - `systemctl stop deepnav` finishes within 2 s, the service exits 0, and its recording is complete
#     and replays (`deepnav replay`).
# A PASS/FAIL table is printed; exit code 0 only when every check passed.
#
#   tools/vm/run-systemd-test.sh [DEEPNAV.deb]
#
# Without a .deb it builds one as tools/package/test_deb.sh does (BUILD_DIR, default build-package/).
# The root file system is made by mmdebstrap (needs root and a Debian mirror, DEBIAN_MIRROR) into
# WORK (default BUILD_DIR/vm-systemd/), as an ext4 image the VM boots from; the kernel is the host's
# Debian linux-image (as tools/vm/run-kernel-tests.sh), with a busybox initramfs that loads virtio and
# ext4 and switches to the image's /sbin/init. DEEPNAV_VM_TIMEOUT_S bounds the VM run (default 600 s);
# DEEPNAV_VM_KEEP_ROOTFS=1 reuses the root directory WORK/rootfs of a previous run and only installs
# this run's .deb there with dpkg (its dependencies must not have changed).
# Not part of CI: see tools/vm/README.md for the measured time.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${BUILD_DIR:-$root/build-package}"
work="${WORK:-$build/vm-systemd}"
mirror="${DEBIAN_MIRROR:-http://deb.debian.org/debian}"
timeout_s="${DEEPNAV_VM_TIMEOUT_S:-600}"
deb="${1:-}"
t_start=$(date +%s)

packages=(qemu-system-x86 busybox-static linux-image-amd64 mmdebstrap e2fsprogs)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "vm-systemd: installing ${missing[*]}"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# --- the package and a dive for the default board --------------------------------------------------------
if [ -z "$deb" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DDEEPNAV_BUILD_TESTS=OFF \
    -DDEEPNAV_BUILD_BENCH=OFF -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache >/dev/null
  ninja -C "$build" -j"${JOBS:-1}" deepnav deepnav-sim
  rm -f "$build"/deepnav_*.deb
  (cd "$build" && cpack -G DEB >/dev/null)
  deb="$(ls "$build"/deepnav_*.deb)"
fi
deb="$(realpath "$deb")"
sim="${DEEPNAV_SIM:-$build/bin/deepnav-sim}"
[ -x "$sim" ] || sim="$(dirname "$(dirname "$deb")")/bin/deepnav-sim"
[ -x "$sim" ] || { echo "vm-systemd: deepnav-sim not found (DEEPNAV_SIM=path)" >&2; exit 2; }
mkdir -p "$work"
# Navigation sensors only: the VM emulates the CPU (TCG), so no stereo pairs for the vision worker.
"$sim" --scenario "$root/tools/sim/scenarios/default.yaml" --no-images --out "$work/dive.mcap" >/dev/null
gcc -O2 -Wall -Wextra -Werror -static -o "$work/stall-thread" "$root/tools/vm/stall_thread.c"

# --- kernel ---------------------------------------------------------------------------------------------
kver=""
for vmlinuz in $(ls -1 /boot/vmlinuz-*-amd64 2>/dev/null | sort -V); do
  v="${vmlinuz#/boot/vmlinuz-}"
  [ -d "/lib/modules/$v/kernel" ] && kver="$v"
done
[ -n "$kver" ] || { echo "vm-systemd: no /boot/vmlinuz-*-amd64 with modules (install linux-image-amd64)" >&2; exit 2; }

# --- the test run inside the VM (a oneshot unit after multi-user.target) -----------------------------------
cat >"$work/deepnav-vmtest" <<'EOF'
#!/bin/bash
# Runs inside the VM as root; writes to the serial console; powers the VM off at the end.
exec >/dev/ttyS0 2>&1
rows=()
failed=0
record() {  # record NAME PASS|FAIL DETAIL
  rows+=("$2|$1|$3")
  [ "$2" = PASS ] || failed=1
  echo "vmtest: $2 $1: $3"
}
prop() { systemctl show -P "$1" deepnav; }
now_ms() { echo $(( $(date +%s%N) / 1000000 )); }
uptime_s() { cut -d' ' -f1 /proc/uptime; }
# Monotonic time (s) of the first journal line of the unit containing TEXT at or after AFTER_S.
journal_t() {
  journalctl -u deepnav -o short-monotonic --no-pager |
    awk -v after="$1" -v pat="$2" '{ t = substr($0, 2, index($0, "]") - 2) + 0; if (t >= after && index($0, pat) > 0) { print t; exit } }'
}
ms_between() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "" || b == "") print ""; else printf "%d", (b - a) * 1000 }'; }

echo "vmtest: systemd $(systemctl --version | head -1), PID 1 is $(cat /proc/1/comm), checks start at $(uptime_s) s after boot"
deepnav run --board /etc/deepnav/board.yaml --validate || true

# 1. Start: `systemctl start` of a Type=notify unit returns when READY=1 came; systemd marks the unit
# active at that moment (ActiveEnterTimestamp), after the service's validation and start-up.
t0=$(now_ms)
systemctl start deepnav; rc=$?
t1=$(now_ms)
state="$(prop ActiveState)/$(prop SubState)"
text="$(prop StatusText)"
ready_ms=$(( ($(prop ActiveEnterTimestampMonotonic) - $(prop ExecMainStartTimestampMonotonic)) / 1000 ))
if [ $rc -eq 0 ] && [ "$state" = active/running ] && [ "$ready_ms" -gt 0 ] && [ -n "$text" ] &&
   journalctl -u deepnav -o cat --no-pager | grep -q '^deepnav run: running'; then
  record "READY=1 -> active" PASS "$state $ready_ms ms after exec (READY=1; systemctl start took $((t1 - t0)) ms)"
else
  record "READY=1 -> active" FAIL "rc $rc, $state, READY after ${ready_ms} ms, status '$text'"
  journalctl -u deepnav --no-pager | tail -20
fi

# 2. The periodic STATUS= in `systemctl status`.
sleep 2.5
status="$(systemctl status deepnav --no-pager -l 2>&1)"
line="$(grep -m1 'Status: "stage' <<<"$status" | sed 's/^ *//')"
if [ -n "$line" ]; then record "STATUS= in systemctl status" PASS "$line"
else record "STATUS= in systemctl status" FAIL "$(head -8 <<<"$status" | tr '\n' ' ')"; fi

# 3. A healthy loop feeds the watchdog: no restart over 3 watchdog periods.
wd="$(prop WatchdogUSec)"
pid0="$(prop MainPID)"
sleep 6
if [ "$(prop NRestarts)" = 0 ] && [ "$(prop MainPID)" = "$pid0" ] && [ "$(prop ActiveState)" = active ]; then
  record "watchdog fed while healthy" PASS "WatchdogUSec=$wd, same PID $pid0 after 6 s, $(prop StatusText | grep -o 'health [a-z -]*|' | tr -d '|')"
else
  record "watchdog fed while healthy" FAIL "NRestarts $(prop NRestarts), PID $pid0 -> $(prop MainPID)"
  journalctl -u deepnav --no-pager | tail -20
fi

# 4. Stall only the nav loop thread: STATUS says stalled, the watchdog fires, systemd restarts it.
n0="$(prop NRestarts)"
t_stall=$(uptime_s)
/usr/local/sbin/stall-thread "$pid0" deepnav-nav 30 &
stall_pid=$!
seen_stalled=""
restarted=""
for _ in $(seq 1 150); do
  sleep 0.1
  [[ "$(prop StatusText)" == *"health stalled"* ]] && seen_stalled=yes
  if [ "$(prop NRestarts)" != "$n0" ] && [ "$(prop MainPID)" != "$pid0" ] && [ "$(prop ActiveState)" = active ]; then
    restarted=yes
    break
  fi
done
kill "$stall_pid" 2>/dev/null; wait "$stall_pid" 2>/dev/null
journal="$(journalctl -u deepnav --no-pager -o cat)"
watchdog_line="$(grep -m1 -i 'watchdog timeout' <<<"$journal")"
t_fired=$(journal_t "$t_stall" "Watchdog timeout")
t_restarted=$(journal_t "$t_stall" "Started deepnav")
if [ -n "$seen_stalled" ]; then record "stalled loop in STATUS=" PASS "'health stalled' in the status text within the stall"
else record "stalled loop in STATUS=" FAIL "never saw 'health stalled'"; fi
if [ -n "$restarted" ] && [ -n "$watchdog_line" ]; then
  record "watchdog kills and restarts" PASS "'$watchdog_line' $(ms_between "$t_stall" "$t_fired") ms after the stall; active again (READY=1) as PID $(prop MainPID) after $(ms_between "$t_stall" "$t_restarted") ms; NRestarts $(prop NRestarts)"
else
  record "watchdog kills and restarts" FAIL "restarted '${restarted:-no}', journal: '${watchdog_line:-no watchdog timeout}'"
  journalctl -u deepnav --no-pager | tail -20
fi

# 5. Stop within 2 s, exit 0, the recording complete and replayable.
sleep 3
pid1="$(prop MainPID)"
t_stop=$(uptime_s)
t0=$(now_ms)
systemctl stop deepnav
t1=$(now_ms)
code="$(prop ExecMainStatus)"; result="$(prop Result)"
# SIGTERM to exit: from systemd's "Stopping" to its "Deactivated successfully" (the process is gone).
stop_ms=$(ms_between "$(journal_t "$t_stop" "Stopping deepnav")" "$(journal_t "$t_stop" "Deactivated successfully")")
if [ -n "$stop_ms" ] && [ "$stop_ms" -lt 2000 ] && [ "$code" = 0 ] && [ "$result" = success ]; then
  record "systemctl stop < 2 s" PASS "SIGTERM to exit $stop_ms ms (systemctl stop returned in $((t1 - t0)) ms), PID $pid1 exited $code, Result=$result"
else
  record "systemctl stop < 2 s" FAIL "SIGTERM to exit ${stop_ms:-?} ms (systemctl stop $((t1 - t0)) ms), exit status $code, Result=$result"
fi
rec="$(ls -1t /var/lib/private/deepnav/recordings/*.mcap 2>/dev/null | head -1)"
if [ -n "$rec" ] && out="$(deepnav replay "$rec" --out /tmp/replay 2>&1)" && ! grep -qi 'truncat' <<<"$out" &&
   compared="$(grep -m1 -o 'outputs compared bit for bit: [0-9]*, mismatches: 0$' <<<"$out")"; then
  record "recording readable" PASS "$(basename "$rec") $(stat -c %s "$rec") bytes, not truncated; deepnav replay: $compared"
else
  record "recording readable" FAIL "${rec:-no recording}: $(tail -3 <<<"${out:-}" | tr '\n' ' ')"
fi

echo
echo "| check | result | detail |"
echo "|---|---|---|"
for r in "${rows[@]}"; do
  IFS='|' read -r res name detail <<<"$r"
  echo "| $name | $res | ${detail//|//} |"
done
echo "vmtest: checks done at $(uptime_s) s after boot"
echo "DEEPNAV_SYSTEMD_RESULT=$failed"
systemctl --no-block poweroff
EOF
chmod +x "$work/deepnav-vmtest"
cat >"$work/deepnav-vmtest.service" <<'EOF'
[Unit]
Description=deepnav systemd contract test (tools/vm/run-systemd-test.sh)
After=multi-user.target
[Service]
Type=oneshot
ExecStart=/usr/local/sbin/deepnav-vmtest
[Install]
WantedBy=multi-user.target
EOF

# --- root file system: Debian 12 with systemd, the .deb installed by apt ------------------------------------
rootfs="$work/rootfs"
img="$work/rootfs.ext4"
t_rootfs=$(date +%s)
if [ "${DEEPNAV_VM_KEEP_ROOTFS:-0}" = 1 ] && [ -x "$rootfs/usr/bin/deepnav" ]; then
  # The .deb of this run replaces the installed one (dpkg: the dependencies must already be there).
  echo "vm-systemd: reusing $rootfs, installing $(basename "$deb") with dpkg"
  cp "$deb" "$rootfs/tmp/"
  chroot "$rootfs" dpkg -i "/tmp/$(basename "$deb")" >/dev/null
  rm -f "$rootfs/tmp/$(basename "$deb")"
else
  rm -rf "$rootfs"
  echo "vm-systemd: mmdebstrap bookworm + systemd + $(basename "$deb") -> $rootfs"
  mmdebstrap --variant=apt --include=systemd,systemd-sysv,procps --quiet \
    --customize-hook="copy-in $deb /tmp" \
    --customize-hook="chroot \"\$1\" apt-get install -y -q /tmp/$(basename "$deb")" \
    --customize-hook='chroot "$1" systemctl mask serial-getty@ttyS0.service getty@tty1.service' \
    --customize-hook='echo deepnav-vm >"$1/etc/hostname"' \
    --customize-hook='rm -f "$1/tmp/'"$(basename "$deb")"'"' \
    bookworm "$rootfs" "$mirror"
fi
# The dive for the default board, and the test (a unit after multi-user.target); the directory stays as
# mmdebstrap left it apart from these, so it can be reused.
mkdir -p "$rootfs/var/lib/deepnav"
cp "$work/dive.mcap" "$rootfs/var/lib/deepnav/dive.mcap"
install -m 0755 "$work/stall-thread" "$work/deepnav-vmtest" "$rootfs/usr/local/sbin/"
install -m 0644 "$work/deepnav-vmtest.service" "$rootfs/etc/systemd/system/"
mkdir -p "$rootfs/etc/systemd/system/multi-user.target.wants"
ln -sf /etc/systemd/system/deepnav-vmtest.service "$rootfs/etc/systemd/system/multi-user.target.wants/"
rm -f "$img"
mkfs.ext4 -q -F -L deepnav-root -d "$rootfs" "$img" 3G
t_boot=$(date +%s)

# --- initramfs: busybox, virtio block and ext4, switch_root to systemd --------------------------------------
ird="$work/initramfs"
rm -rf "$ird"
mkdir -p "$ird"/{bin,dev,proc,sys,newroot,modules}
cp /bin/busybox "$ird/bin/busybox"
for applet in sh mount umount insmod sleep switch_root echo cat; do ln -s busybox "$ird/bin/$applet"; done
source "$root/tools/vm/boot_modules.sh"
copy_boot_modules "$kver" "$ird" virtio_pci virtio_blk crc32c_generic ext4
cat >"$ird/init" <<'EOF'
#!/bin/sh
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev
for ko in $(cat /modules/order); do insmod "/modules/$ko" 2>/dev/null; done
for _ in 1 2 3 4 5 6 7 8 9 10; do [ -b /dev/vda ] && break; sleep 0.5; done
if ! mount -t ext4 -o rw /dev/vda /newroot; then echo "DEEPNAV_SYSTEMD_RESULT=3"; exec sh; fi
umount /proc /sys
mount --move /dev /newroot/dev 2>/dev/null || umount /dev
exec switch_root /newroot /sbin/init
EOF
chmod +x "$ird/init"
(cd "$ird" && find . | cpio -o -H newc --quiet) >"$work/initramfs.cpio"

# --- boot -------------------------------------------------------------------------------------------------
log="$work/console.log"
echo "vm-systemd: booting $kver with systemd under TCG (log: $log)"
set +e
timeout "$timeout_s" qemu-system-x86_64 \
  -accel tcg -cpu max -smp 2 -m 2048 \
  -kernel "/boot/vmlinuz-$kver" -initrd "$work/initramfs.cpio" \
  -append "console=ttyS0 panic=-1 quiet loglevel=3 rdinit=/init systemd.show_status=0 rw" \
  -drive "file=$img,format=raw,if=virtio" \
  -nographic -no-reboot -monitor none -serial "file:$log" -display none -nic none
qemu_rc=$?
set -e
t_end=$(date +%s)
sed -e 's/\r$//' "$log" | grep -a -E '^(vmtest:|\||DEEPNAV_SYSTEMD_RESULT)' || true
echo "vm-systemd: rootfs $((t_boot - t_rootfs)) s, VM run $((t_end - t_boot)) s, in all $((t_end - t_start)) s (qemu exit $qemu_rc)"
result="$(sed -n 's/^DEEPNAV_SYSTEMD_RESULT=\([0-9]*\).*/\1/p' "$log" | tail -1)"
if [ -z "$result" ]; then
  echo "vm-systemd: no result from the VM (timeout after ${timeout_s} s or boot failure; see $log)" >&2
  exit 1
fi
exit "$result"
