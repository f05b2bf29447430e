# Sourced by run-kernel-tests.sh and run-systemd-test.sh (bash).
# copy_boot_modules KVER IRD MODULE...: copies the named modules of kernel KVER and their dependencies
# (from modinfo) into IRD/modules, and writes their file names in load order (dependencies first) to
# IRD/modules/order, which the initramfs's /init insmods in turn. Modules built into the kernel are
# skipped.
copy_boot_modules() {
  local kver="$1" ird="$2" m f
  shift 2
  local -A seen=()
  local order=()
  _add_boot_module() {  # sees kver, seen and order of its caller (bash scoping is dynamic)
    local name="$1" dep
    [ -n "${seen[$name]:-}" ] && return 0
    seen[$name]=1
    for dep in $(modinfo -k "$kver" -F depends "$name" | tr ',' ' '); do _add_boot_module "$dep"; done
    order+=("$name")
  }
  for m in "$@"; do _add_boot_module "$m"; done
  : >"$ird/modules/order"
  for m in "${order[@]}"; do
    f="$(modinfo -k "$kver" -F filename "$m")"
    if [ "$f" = "(builtin)" ] || [ -z "$f" ]; then continue; fi
    cp "$f" "$ird/modules/"
    basename "$f" >>"$ird/modules/order"
  done
}
