#!/usr/bin/env bash
# Installs whatever D-former's build and tests need and is missing; skips what is present.
# Safe to run again. Used by demo.sh and test.sh; nothing else needs to be installed by hand.
#
#   scripts/setup.sh           toolchain for the core + Node deps (enough for the demo)
#   scripts/setup.sh --all     also the test browser (Chromium), Inkscape, and what the release
#                              packages need (scripts/setup-release.sh)
set -euo pipefail
cd "$(dirname "$0")/.."

want_all=0
[ "${1:-}" = "--all" ] && want_all=1

say() { printf '\033[1msetup:\033[0m %s\n' "$*"; }

export PATH="$HOME/.cargo/bin:$PATH"
command -v cargo >/dev/null || { echo "setup: cargo not found. Install Rust from rustup first." >&2; exit 1; }
command -v node >/dev/null || { echo "setup: node not found. Install Node.js 20 or newer first." >&2; exit 1; }

# 1. The WebAssembly target.
if ! rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown; then
  say "adding the wasm32-unknown-unknown target"
  rustup target add wasm32-unknown-unknown
fi

# 2. wasm-bindgen CLI, pinned to exactly the wasm-bindgen crate version in Cargo.lock.
wbg_version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
[ -n "$wbg_version" ] || { echo "setup: cannot read the wasm-bindgen version from Cargo.lock" >&2; exit 1; }
if [ "$(wasm-bindgen --version 2>/dev/null | awk '{print $2}')" != "$wbg_version" ]; then
  say "installing wasm-bindgen-cli $wbg_version (a few minutes, once)"
  cargo install wasm-bindgen-cli --version "=$wbg_version" --locked
fi

# 3. wasm-pack (it uses the wasm-bindgen above; its wasm-opt step is off in core/Cargo.toml, and
#    scripts/wasm-opt.mjs runs binaryen from the Node dependencies instead).
if ! command -v wasm-pack >/dev/null; then
  say "installing wasm-pack (a few minutes, once)"
  cargo install wasm-pack --locked
fi

# 4. Node dev dependencies (test browser driver, ESLint, TypeScript, Illustrator typings, binaryen).
if [ ! -d node_modules ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  say "installing Node dependencies"
  npm ci --no-audit --no-fund --loglevel=error
fi

# 5. For the full test suite: Debian's Chromium (Playwright drives it), Inkscape 1.x with the
#    Python modules its extensions import, Xvfb (Inkscape registers extension actions only
#    with a display) and xdotool (the refusal tests close Inkscape's message dialog).
if [ "$want_all" = 1 ]; then
  missing=()
  command -v chromium >/dev/null || missing+=(chromium)
  command -v inkscape >/dev/null || missing+=(inkscape)
  command -v xvfb-run >/dev/null || missing+=(xvfb)
  command -v xauth >/dev/null || missing+=(xauth)
  command -v xdotool >/dev/null || missing+=(xdotool)
  # The modules Inkscape's inkex imports on load (Debian only recommends them, so an Inkscape
  # installed without recommends lacks them).
  for pair in lxml:python3-lxml numpy:python3-numpy cssselect:python3-cssselect; do
    /usr/bin/python3 -c "import ${pair%%:*}" 2>/dev/null || missing+=("${pair#*:}")
  done
  [ ${#missing[@]} -eq 0 ] || bash scripts/apt-install.sh "${missing[@]}"
  # 6. The release packages and their proofs: cross targets, MinGW, musl, wine64, shellcheck, zig.
  bash scripts/setup-release.sh >/dev/null
fi
say "ready"
