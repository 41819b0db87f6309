#!/usr/bin/env bash
# Builds every release artifact into dist/release/, named with the one project version
# ([workspace.package] version in Cargo.toml), from a fresh checkout: installs what is missing
# (scripts/setup.sh, scripts/setup-release.sh), skips what is present.
#
#   d-former-VERSION-inkscape-linux-x86_64.zip    extension + static dformer (musl)
#   d-former-VERSION-inkscape-windows-x86_64.zip  extension + dformer.exe (x86_64-pc-windows-gnu, MinGW)
#   d-former-VERSION-inkscape-macos.zip           extension + universal dformer (arm64 + x86_64, zig)
#   d-former-VERSION-illustrator.zip              CEP panel + install/uninstall for macOS and Windows
#   d-former-VERSION.html                         the browser app in one file, works offline
#   SHA256SUMS
#
# Usage: bash scripts/package.sh [--reuse-panel]
#   --reuse-panel  use dist/com.dformer.panel and dist/d-former.html as built by
#                  `node uxp-panel/build.mjs` (test.sh has just run it) instead of building them again.
set -euo pipefail
cd "$(dirname "$0")/.."
repo="$(pwd)"
reuse_panel=0
for arg in "$@"; do
  case "$arg" in
    --reuse-panel) reuse_panel=1 ;;
    -h|--help) sed -n 2,17p "$0"; exit 0 ;;
    *) echo "package.sh: unknown argument $arg" >&2; exit 2 ;;
  esac
done

say() { printf '\033[1mpackage:\033[0m %s\n' "$*"; }
timed() { # timed LABEL COMMAND...: runs it and prints how long it took
  local label="$1" start=$SECONDS; shift
  "$@"
  say "$label: $((SECONDS - start)) s"
}

bash scripts/setup.sh
venv_bin="$(bash scripts/setup-release.sh | tail -n 1)"
export PATH="$venv_bin:$HOME/.cargo/bin:$PATH"

version="$(sed -n '/^\[workspace\.package\]/,/^\[/s/^version = "\(.*\)"/\1/p' Cargo.toml)"
[ -n "$version" ] || { echo "package.sh: no [workspace.package] version in Cargo.toml" >&2; exit 1; }
npm_version="$(node -p 'require("./package.json").version')"
[ "$npm_version" = "$version" ] || {
  echo "package.sh: package.json says version $npm_version but Cargo.toml says $version; set both to one version" >&2
  exit 1
}
say "version $version"

target_dir="${CARGO_TARGET_DIR:-target}"
out=dist/release
stage="dist/release-stage"
rm -rf "$out" "$stage"
mkdir -p "$out" "$stage"

# --- 1. the dformer program for each platform (release profile: LTO, one codegen unit, stripped)
# Linux (musl: static) and Windows (MinGW's linker) in one cargo run, so the two single-threaded
# LTO links at the end run side by side on two cores.
export CARGO_TARGET_X86_64_PC_WINDOWS_GNU_LINKER=x86_64-w64-mingw32-gcc
timed "dformer for Linux x86_64 (musl, static) and Windows x86_64 (MinGW)" \
  nice cargo build --quiet --release --locked -p dformer-cli --target x86_64-unknown-linux-musl --target x86_64-pc-windows-gnu
# cargo-zigbuild builds aarch64-apple-darwin and x86_64-apple-darwin with zig as the linker
# (zig ships macOS's libSystem stubs, so no Apple SDK is needed) and joins them into one fat file.
# Without a deployment target zig would stamp its own newest macOS (15.0) as the minimum; 11.0
# (Big Sur, 2020) is the first with Apple silicon, and the oldest that most students' Macs run.
export MACOSX_DEPLOYMENT_TARGET="${MACOSX_DEPLOYMENT_TARGET:-11.0}"
timed "dformer for macOS arm64 + x86_64 (zig, universal)" \
  nice cargo zigbuild --quiet --release --locked -p dformer-cli --target universal2-apple-darwin
linux_bin="$target_dir/x86_64-unknown-linux-musl/release/dformer"
windows_bin="$target_dir/x86_64-pc-windows-gnu/release/dformer.exe"
macos_bin="$target_dir/universal2-apple-darwin/release/dformer"
got="$("$linux_bin" --version)"
[ "$got" = "dformer $version" ] || { echo "package.sh: $linux_bin --version says '$got', not 'dformer $version'" >&2; exit 1; }

# --- 2. the Inkscape extension, one zip per platform: unzip into Inkscape's user extensions folder
inkscape_zip() { # inkscape_zip PLATFORM BINARY NAME_IN_ZIP
  local dir="$stage/inkscape-$1/dformer"
  mkdir -p "$dir"
  cp inkscape-extension/dformer_*.py "$dir/"
  for inx in inkscape-extension/dformer_*.inx; do
    # The version shows in each dialog: appended to the first <label> (the dialog's description).
    sed "0,/<\/label>/s|</label>| (D-former $version)</label>|" "$inx" > "$dir/$(basename "$inx")"
  done
  sed "s/@VERSION@/$version/g" release/inkscape/README.txt > "$dir/README.txt"
  cp "$2" "$dir/$3"
  chmod 755 "$dir/$3"
  python3 release/zipdir.py "$out/d-former-$version-inkscape-$1.zip" "$stage/inkscape-$1"
}
inkscape_zip linux-x86_64 "$linux_bin" dformer
inkscape_zip windows-x86_64 "$windows_bin" dformer.exe
inkscape_zip macos "$macos_bin" dformer

# --- 3. the Illustrator panel and the browser app (uxp-panel/build.mjs), then the CEP zip
if [ "$reuse_panel" = 0 ] || [ ! -f dist/com.dformer.panel/CSXS/manifest.xml ] || [ ! -f dist/d-former.html ]; then
  timed "Illustrator panel and browser app (node uxp-panel/build.mjs)" node uxp-panel/build.mjs
fi
grep -q "ExtensionBundleVersion=\"$version\"" dist/com.dformer.panel/CSXS/manifest.xml || {
  echo "package.sh: dist/com.dformer.panel is not version $version; run node uxp-panel/build.mjs" >&2
  exit 1
}
cep="$stage/illustrator/d-former-$version-illustrator"
mkdir -p "$cep"
cp -R dist/com.dformer.panel "$cep/"
cp release/cep/install-macos.command release/cep/uninstall-macos.command \
  release/cep/install-windows.cmd release/cep/uninstall-windows.cmd "$cep/"
chmod 755 "$cep"/*.command
sed "s/@VERSION@/$version/g" release/cep/README.txt > "$cep/README.txt"
python3 release/zipdir.py "$out/d-former-$version-illustrator.zip" "$stage/illustrator"
cp dist/d-former.html "$out/d-former-$version.html"

# --- 4. checksums
(cd "$out" && sha256sum -- *.zip *.html > SHA256SUMS)
rm -rf "$stage"
say "wrote $repo/$out:"
(cd "$out" && ls -l)
