#!/usr/bin/env bash
# ./wheelchair package: the whole stack as one Debian package, out/package/wheelchair_<v>_<arch>.deb
#
#   1. catkin_make install of src/ + test/ (Release, testing off, generic x86-64: no -march=native)
#      in its own workspace (default out/package/ws; WHEELCHAIR_PACKAGE_WS to reuse a build),
#      with CMAKE_INSTALL_PREFIX=/opt/wheelchair, staged with DESTDIR;
#   2. the files of deploy/: systemd unit (shipped, not enabled), the boot script, the CAN
#      set-up script, /etc/default/wheelchair (a conffile), the docs;
#   3. Depends: the shared libraries every ELF file needs (dpkg-shlibdeps = ldd + the
#      libraries' shlibs/symbols files, with minimum versions) + the runtime tools listed in
#      deploy/runtime-depends.txt (each in tools/debian-packages.txt or known to apt);
#   4. dpkg-deb --build --root-owner-group.
# Installs with `apt-get install ./out/package/wheelchair_*.deb`; test: deploy/test-install.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
PREFIX="${WHEELCHAIR_PREFIX:-/opt/wheelchair}"
OUT="$ROOT/out/package"
WS="${WHEELCHAIR_PACKAGE_WS:-$OUT/ws}"
NAME=wheelchair
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"

say() { printf '\033[1m[package]\033[0m %s\n' "$*"; }
die() { printf '[package] error: %s\n' "$*" >&2; exit 1; }

# CPU baseline: the compiler's default, which must be generic x86-64 on amd64 (Debian's gcc:
# -march=x86-64 -mtune=generic = SSE2, no AVX); CXXFLAGS/CFLAGS from the environment are dropped
# and any -march=native in the build fails the packaging.
check_cpu_baseline() {
  [ "$(dpkg --print-architecture)" = amd64 ] || return 0
  local march
  march=$(g++ -Q --help=target 2>/dev/null | awk '$1 == "-march=" {print $2}')
  [ "$march" = x86-64 ] || die "g++ targets -march=$march by default, not the generic x86-64"
}

build_install_space() {
  local stage="$1"
  mkdir -p "$WS/src"
  local pkg
  for pkg in "$ROOT"/src/*/; do ln -sfn "${pkg%/}" "$WS/src/"; done
  ln -sfn "$ROOT/test" "$WS/src/wheelchair_test"
  local launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  check_cpu_baseline
  say "building the install space in $WS (Release, -j2, prefix $PREFIX, generic x86-64)"
  rm -rf "$stage"
  (cd "$WS" && env -u CXXFLAGS -u CFLAGS DESTDIR="$stage" catkin_make -j2 install \
      -DCMAKE_BUILD_TYPE=Release -DCATKIN_ENABLE_TESTING=OFF \
      -DCMAKE_INSTALL_PREFIX="$PREFIX" \
      -DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3 \
      "${launcher[@]}") > "$OUT/build.log" 2>&1 || { tail -30 "$OUT/build.log"; die "build failed (out/package/build.log)"; }
  if grep -rl -e '-march=native' -e '-mtune=native' "$WS/build" --include=flags.make --include=link.txt >/dev/null; then
    die "a target is compiled with -march=native: the package would not run on other CPUs"
  fi
}

add_deploy_files() {
  local stage="$1"
  install -D -m 644 "$ROOT/deploy/wheelchair.service" "$stage/lib/systemd/system/wheelchair.service"
  install -D -m 644 "$ROOT/deploy/wheelchair.default" "$stage/etc/default/wheelchair"
  install -D -m 755 "$ROOT/deploy/wheelchair-up" "$stage$PREFIX/lib/wheelchair/wheelchair-up"
  install -D -m 755 "$ROOT/deploy/can-up" "$stage$PREFIX/lib/wheelchair/can-up"
  install -D -m 755 "$ROOT/deploy/netns-up" "$stage$PREFIX/lib/wheelchair/netns-up"
  install -D -m 755 "$ROOT/deploy/check-isolation" "$stage$PREFIX/lib/wheelchair/check-isolation"
  install -D -m 644 "$ROOT/deploy/wheelchair-netns.service" \
    "$stage/lib/systemd/system/wheelchair-netns.service"
  install -D -m 644 "$ROOT/deploy/wheelchair-display.service" \
    "$stage/lib/systemd/system/wheelchair-display.service"
  install -D -m 755 "$ROOT/deploy/display-up" "$stage$PREFIX/lib/wheelchair/display-up"
  install -D -m 644 "$ROOT/deploy/README.md" "$stage/usr/share/doc/$NAME/README.md"
  install -D -m 644 "$ROOT/README.md" "$stage/usr/share/doc/$NAME/README.project.md"
}

# Depends from the ELF files (dpkg-shlibdeps needs a debian/control and the staged tree at
# debian/<package>/, where it finds the package's own libraries) + the runtime tools.
depends() {
  local pkgroot="$1" elves
  elves=$(find "$pkgroot" -type f -exec sh -c 'head -c4 "$1" | grep -q ELF && echo "$1"' _ {} \;)
  [ -n "$elves" ] || die "no ELF file in the install space"
  local shlibs
  shlibs=$(cd "$(dirname "$(dirname "$pkgroot")")" &&
           dpkg-shlibdeps -O -l"$pkgroot$PREFIX/lib" --ignore-missing-info $elves 2>"$OUT/shlibdeps.log" |
           sed -n 's/^shlibs:Depends=//p')
  [ -n "$shlibs" ] || { cat "$OUT/shlibdeps.log" >&2; die "dpkg-shlibdeps found no dependency"; }
  local tool tools=()
  while read -r tool; do
    debian_packages_has "$tool" || apt-cache show "$tool" >/dev/null 2>&1 ||
      die "deploy/runtime-depends.txt: $tool is neither in tools/debian-packages.txt nor known to apt"
    tools+=("$tool")
  done < <(grep -v -e '^#' -e '^[[:space:]]*$' "$ROOT/deploy/runtime-depends.txt")
  local IFS=,
  echo "$shlibs, ${tools[*]}" | sed 's/,\([^ ]\)/, \1/g'
}

debian_packages_has() { grep -qx "$1" "$ROOT/tools/debian-packages.txt"; }

version() {
  local base commit
  base=$(sed -n 's:.*<version>\(.*\)</version>.*:\1:p' "$ROOT/src/wheelchair_bringup/package.xml")
  commit=$(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo 0)
  echo "$base+git$(git -C "$ROOT" log -1 --format=%cd --date=format:%Y%m%d 2>/dev/null || date +%Y%m%d).$commit"
}

write_control() {
  local pkgroot="$1" deps="$2" arch version size
  arch=$(dpkg --print-architecture)
  version=$(version)
  size=$(du -sk --exclude=DEBIAN "$pkgroot" | cut -f1)
  mkdir -p "$pkgroot/DEBIAN"
  cat > "$pkgroot/DEBIAN/control" <<EOF
Package: $NAME
Version: $version
Architecture: $arch
Maintainer: Wheelchair developers <wheelchair-dev@example.org>
Installed-Size: $size
Depends: $deps
Section: misc
Priority: optional
Description: autonomous wheelchair stack (ROS 1 nodelets, MRPT) under $PREFIX
 Map server, KLD localizer, harmonic/OMPL planner, dynamic-model controller, CAN base
 driver, safety supervisor and one-switch HMI in one nodelet process
 (rosrun wheelchair_bringup wheelchair CONFIG), the simulator and test worlds.
 Built for a generic $arch CPU$( [ "$arch" = amd64 ] && echo " (x86-64 baseline: SSE2, no AVX)").
 Boot services wheelchair.service (the chair) and wheelchair-display.service (the
 rider's screen, a cage kiosk on tty1) are shipped but not enabled:
 systemctl enable --now wheelchair (config: /etc/default/wheelchair).
EOF
  echo "/etc/default/wheelchair" > "$pkgroot/DEBIAN/conffiles"
}

main() {
  mkdir -p "$OUT"
  local work="$OUT/deb" pkgroot
  pkgroot="$work/debian/$NAME"
  if [ "${WHEELCHAIR_PACKAGE_SKIP_BUILD:-0}" = 1 ] && [ -d "$pkgroot$PREFIX" ]; then
    say "reusing the staged install space $pkgroot"
    rm -rf "$pkgroot/DEBIAN"
  else
    build_install_space "$pkgroot"
  fi
  add_deploy_files "$pkgroot"
  mkdir -p "$work/debian"
  printf 'Source: %s\n\nPackage: %s\nArchitecture: any\n' "$NAME" "$NAME" > "$work/debian/control"
  say "deriving Depends (dpkg-shlibdeps over every ELF file + deploy/runtime-depends.txt)"
  local deps
  deps=$(depends "$pkgroot")
  write_control "$pkgroot" "$deps"
  rm -f "$OUT"/*.deb
  local deb="$OUT/${NAME}_$(version)_$(dpkg --print-architecture).deb"
  dpkg-deb --build --root-owner-group -Zxz "$pkgroot" "$deb" >/dev/null
  say "$deb ($(du -h "$deb" | cut -f1)); Depends:"
  echo "$deps" | tr ',' '\n' | sed 's/^ */  /'
}

main "$@"
