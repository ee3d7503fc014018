#!/usr/bin/env bash
# Builds radiant's Debian package with CPack, installs it with apt-get, and renders the bundled
# default scene with the installed /usr/bin/radiant (PNG, and EXR through the installed
# OpenImageIO module), so CI proves the package works on the machine that runs the tests.
# Usage: scripts/package.sh [BUILD_DIR]   (a Release build folder; scripts/setup.sh makes one)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
scripts/setup.sh "$build_dir" >/dev/null
(cd "$build_dir" && rm -f radiant_*.deb && cpack -G DEB >/dev/null)
package=$(ls "$build_dir"/radiant_*.deb)
echo "package: $package"
dpkg-deb --field "$package" Depends
sudo_cmd=(); [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --reinstall "./$package" >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/radiant --version
/usr/bin/radiant render /usr/share/radiant/assets/cornell.gltf -o "$work/cornell.png" --width 64 --height 64 --spp 4 --quiet
/usr/bin/radiant render /usr/share/radiant/assets/cornell.gltf -o "$work/cornell.exr" --width 64 --height 64 --spp 4 --quiet
test -s "$work/cornell.png" && test -s "$work/cornell.exr"
ls /usr/share/man/man1/radiant.1* /usr/share/bash-completion/completions/radiant /usr/share/zsh/vendor-completions/_radiant >/dev/null
echo "package: installed, and the installed radiant rendered the default scene"
