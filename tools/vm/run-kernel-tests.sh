#!/usr/bin/env bash
# Runs the tests that need kernel drivers this machine's kernel lacks (vivid for V4L2, vcan for
# SocketCAN) inside a small QEMU VM: qemu-system-x86 under TCG, Debian's linux-image kernel and a
# busybox initramfs. The VM mounts the host's root file system read-only over 9p (virtio) and chroots
# into it, so the test binaries run with the host's shared libraries and the kernel's own modules.
#
#   tools/vm/run-kernel-tests.sh [BUILD_DIR] [TEST_BINARY...]
#
# BUILD_DIR defaults to build/; the test binaries default to drivers_vivid_test and drivers_vcan_test
# in BUILD_DIR/bin. Exit code: 0 when every test binary ran and passed with no test skipped.
# Missing Debian packages (qemu-system-x86, busybox-static, linux-image-amd64) are installed with apt
# unless DEEPNAV_VM_NO_INSTALL=1. DEEPNAV_VM_TIMEOUT_S bounds the whole VM run (default 600 s).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${1:-$root/build}"
build_dir="$(cd "$build_dir" && pwd)"
shift || true
tests=("$@")
if [ "${#tests[@]}" -eq 0 ]; then
  tests=("$build_dir/bin/drivers_vivid_test" "$build_dir/bin/drivers_vcan_test")
fi
timeout_s="${DEEPNAV_VM_TIMEOUT_S:-600}"

# --- packages ----------------------------------------------------------------------------------------
packages=(qemu-system-x86 busybox-static linux-image-amd64)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  if [ "${DEEPNAV_VM_NO_INSTALL:-0}" = 1 ]; then
    echo "vm: missing Debian packages: ${missing[*]} (apt-get install --no-install-recommends ${missing[*]})" >&2
    exit 2
  fi
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  echo "vm: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -q
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# --- kernel: the newest Debian amd64 image whose modules are installed -------------------------------
kver=""
for vmlinuz in $(ls -1 /boot/vmlinuz-*-amd64 2>/dev/null | sort -V); do
  v="${vmlinuz#/boot/vmlinuz-}"
  [ -d "/lib/modules/$v/kernel" ] && kver="$v"
done
if [ -z "$kver" ]; then
  echo "vm: no /boot/vmlinuz-*-amd64 with modules in /lib/modules (install linux-image-amd64)" >&2
  exit 2
fi
moddir="/lib/modules/$kver"

for i in "${!tests[@]}"; do
  t="${tests[$i]}"
  if [ -x "$t" ]; then tests[$i]="$(realpath "$t")"; t="${tests[$i]}"; fi
  if [ ! -x "$t" ]; then
    echo "vm: test binary $t not found (build it first: ninja -C $build_dir $(basename "$t"))" >&2
    exit 2
  fi
done

# --- initramfs: busybox, the modules needed to mount the host over 9p, and /init --------------------
work="$build_dir/vm"
rm -rf "$work/initramfs"
mkdir -p "$work/initramfs"/{bin,dev,proc,sys,host,modules}
ird="$work/initramfs"
cp /bin/busybox "$ird/bin/busybox"
for applet in sh mount umount insmod mkdir chroot poweroff echo cat sleep; do
  ln -s busybox "$ird/bin/$applet"
done

# The boot modules and their dependencies, in load order (dependencies first).
source "$root/tools/vm/boot_modules.sh"
copy_boot_modules "$kver" "$ird" virtio_pci 9pnet_virtio 9p

# The commands run inside the VM, in the host's root (chroot). A skipped test counts as a failure:
# in the VM the kernel drivers must be there.
{
  echo 'export HOME=/tmp TMPDIR=/tmp PATH=/usr/sbin:/usr/bin:/sbin:/bin'
  echo 'modprobe vivid n_devs=2 node_types=0x1,0x1 || echo "vm: modprobe vivid failed"'
  echo 'for m in vcan can_raw; do modprobe "$m" || echo "vm: modprobe $m failed"; done'
  echo 'ip link add dev vcan0 type vcan 2>/dev/null && ip link set vcan0 up'
  echo 'overall=0'
  for t in "${tests[@]}"; do
    echo "echo \"vm: running $t\""
    echo "t0=\$(date +%s%N)"
    echo "\"$t\" --gtest_color=no >/tmp/out.txt 2>&1; rc=\$?"
    echo 'cat /tmp/out.txt'
    echo "t1=\$(date +%s%N)"
    echo "if grep -q '^\[  SKIPPED \]' /tmp/out.txt; then echo \"vm: $(basename "$t") skipped tests\"; rc=1; fi"
    echo "echo \"vm: $(basename "$t") rc=\$rc time=\$(( (t1 - t0) / 1000000 )) ms\""
    echo '[ "$rc" -eq 0 ] || overall=1'
  done
  echo 'echo "DEEPNAV_VM_RESULT=$overall"'
} >"$ird/run-tests.sh"

cat >"$ird/init" <<'EOF'
#!/bin/sh
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev
for ko in $(cat /modules/order); do insmod "/modules/$ko" || echo "vm: insmod $ko failed"; done
if ! mount -t 9p -o trans=virtio,version=9p2000.L,ro,cache=loose hostroot /host; then
  echo "DEEPNAV_VM_RESULT=3"; poweroff -f
fi
mount -t proc proc /host/proc
mount -t sysfs sys /host/sys
mount -t devtmpfs dev /host/dev
mount -t tmpfs tmp /host/tmp
mount -t tmpfs run /host/run
# The test binaries' folders as their own shares, at their host paths: a build under /tmp (hidden by the
# tmpfs above) or on another file system is then visible in the chroot too.
while read -r tag dir; do
  mkdir -p "/host$dir" 2>/dev/null
  mount -t 9p -o trans=virtio,version=9p2000.L,ro,cache=loose "$tag" "/host$dir" || echo "vm: cannot mount $dir"
done </testdirs
chroot /host /bin/sh -s </run-tests.sh
poweroff -f
EOF
chmod +x "$ird/init"
# One 9p share per folder holding a test binary (mounted by /init at the same path).
share_args=()
: >"$ird/testdirs"
i=0
for d in $(for t in "${tests[@]}"; do dirname "$t"; done | sort -u); do
  echo "tests$i $d" >>"$ird/testdirs"
  share_args+=(-virtfs "local,path=$d,mount_tag=tests$i,security_model=none,readonly=on,id=tests$i")
  i=$((i + 1))
done
(cd "$ird" && find . | cpio -o -H newc --quiet) >"$work/initramfs.cpio"

# --- boot -----------------------------------------------------------------------------------------------
log="$work/console.log"
echo "vm: booting $kver under TCG (log: $log)"
start_s=$(date +%s)
set +e
timeout "$timeout_s" qemu-system-x86_64 \
  -accel tcg -cpu max -smp 2 -m 2048 \
  -kernel "/boot/vmlinuz-$kver" -initrd "$work/initramfs.cpio" \
  -append "console=ttyS0 panic=-1 quiet loglevel=3 rdinit=/init" \
  -virtfs local,path=/,mount_tag=hostroot,security_model=none,readonly=on,multidevs=remap,id=hostroot \
  "${share_args[@]}" \
  -nographic -no-reboot -monitor none -serial "file:$log" -display none \
  -nic none
qemu_rc=$?
set -e
end_s=$(date +%s)
sed -e 's/\r$//' "$log" | grep -v '^\s*$' || true
echo "vm: whole VM run took $((end_s - start_s)) s (qemu exit $qemu_rc)"
result="$(sed -n 's/^DEEPNAV_VM_RESULT=\([0-9]*\).*/\1/p' "$log" | tail -1)"
if [ -z "$result" ]; then
  echo "vm: no result from the VM (timeout after ${timeout_s} s or crash)" >&2
  exit 1
fi
exit "$result"
