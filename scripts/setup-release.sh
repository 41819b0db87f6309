#!/usr/bin/env bash
# Installs what the release packages (scripts/package.sh) and their proofs (tests/release/) need and
# is missing; skips what is present. Called by `scripts/setup.sh --all` and by package.sh.
#   - Rust standard libraries for the four release targets (rustup);
#   - Debian: gcc-mingw-w64-x86-64 (Windows linker), musl-tools (static Linux), wine64 (runs the
#     Windows dformer.exe in the tests), shellcheck (the macOS installer), unzip (the tests unzip
#     as users do; the zips themselves are written by release/zipdir.py);
#   - PyPI, in a venv of their own (DFORMER_RELEASE_VENV, default ~/.cache/dformer-release/venv):
#     ziglang (zig as a cross linker with macOS's libSystem stubs) and cargo-zigbuild (drives it,
#     and joins the two macOS binaries into one universal binary).
# Prints nothing but what it installs; ends with the venv's bin directory on its last line, which
# package.sh puts on PATH.
set -euo pipefail
cd "$(dirname "$0")/.."

say() { printf '\033[1msetup-release:\033[0m %s\n' "$*" >&2; }
export PATH="$HOME/.cargo/bin:$PATH"

targets=(x86_64-unknown-linux-musl x86_64-pc-windows-gnu aarch64-apple-darwin x86_64-apple-darwin)
installed="$(rustup target list --installed 2>/dev/null)"
missing_targets=()
for t in "${targets[@]}"; do grep -qx "$t" <<<"$installed" || missing_targets+=("$t"); done
if [ ${#missing_targets[@]} -gt 0 ]; then
  say "adding Rust targets ${missing_targets[*]}"
  rustup target add "${missing_targets[@]}" >&2
fi

missing=()
command -v x86_64-w64-mingw32-gcc >/dev/null || missing+=(gcc-mingw-w64-x86-64)
command -v musl-gcc >/dev/null || missing+=(musl-tools)
command -v shellcheck >/dev/null || missing+=(shellcheck)
command -v unzip >/dev/null || missing+=(unzip)
[ -x /usr/lib/wine/wine64 ] || command -v wine64 >/dev/null || missing+=(wine64)
[ ${#missing[@]} -eq 0 ] || bash scripts/apt-install.sh "${missing[@]}"

venv="${DFORMER_RELEASE_VENV:-$HOME/.cache/dformer-release/venv}"
if [ ! -x "$venv/bin/cargo-zigbuild" ] || ! "$venv/bin/python3" -m ziglang version >/dev/null 2>&1; then
  say "installing ziglang and cargo-zigbuild from PyPI into $venv"
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check ziglang cargo-zigbuild >&2
fi
echo "$venv/bin"
