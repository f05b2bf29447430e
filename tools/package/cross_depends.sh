#!/usr/bin/env bash
# Depends: line for a cross-built binary (the arm64 .deb), from the host's Debian 12 packages.
# dpkg-shlibdeps cannot run on a cross build: the arm64 sysroot is unpacked by mmdebstrap without a dpkg
# database, so it cannot say which package owns a library. The library packages of one Debian release
# have the same names and versions on every architecture (libopencv-core406 4.6.0+dfsg on amd64 and
# arm64), so each library the binary needs (ELF NEEDED) is looked up on the host instead: the package
# owning the host's copy of that soname, and the dependency its shlibs file declares (deb-shlibs(5): the
# same rule dpkg-shlibdeps applies when a package has no symbols file); without a shlibs line,
# "package (>= installed upstream version)".
# Usage: tools/package/cross_depends.sh BINARY   prints "pkg (>= v), pkg2, ..." on stdout.
set -euo pipefail
binary="$1"
multiarch="$(gcc -print-multiarch)"
deps=()
while read -r soname; do
  path=""
  for dir in "/usr/lib/$multiarch" "/lib/$multiarch"; do
    owner="$(dpkg-query -S "$dir/$soname" 2>/dev/null | head -1 | cut -d: -f1 || true)"
    if [ -n "$owner" ]; then path="$dir/$soname"; break; fi
  done
  if [ -z "$path" ]; then
    echo "cross_depends: $binary needs $soname, which no host package provides (install its -dev package)" >&2
    exit 1
  fi
  name="${soname%%.so*}"
  version="${soname#*.so.}"
  [ "$version" = "$soname" ] && version=""
  line=""
  for f in "/var/lib/dpkg/info/$owner:$(dpkg --print-architecture).shlibs" "/var/lib/dpkg/info/$owner.shlibs"; do
    if [ -f "$f" ]; then
      line="$(awk -v n="$name" -v v="$version" '$1 == n && $2 == v && $0 !~ /^[a-z]+:/ { $1 = ""; $2 = ""; sub(/^ +/, ""); print; exit }' "$f")"
      [ -n "$line" ] && break
    fi
  done
  if [ -z "$line" ]; then
    upstream="$(dpkg-query -W -f='${Version}' "$owner" | sed 's/-[^-]*$//')"
    line="$owner (>= $upstream)"
  fi
  deps+=("$(echo "$line" | sed 's/:[a-z0-9]*\b//g')")
done < <(readelf -d "$binary" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
printf '%s\n' "${deps[@]}" | sort -u | paste -sd, - | sed 's/,/, /g'
