#!/usr/bin/env bash
# Installs the D-former Inkscape extension (Linux and macOS): builds the `dformer` core program
# with cargo (or takes a prebuilt one) and copies it with the .inx/.py files into
# <Inkscape user data directory>/extensions/dformer.
#
#   inkscape-extension/install.sh                 # build (release) and install for this user
#   inkscape-extension/install.sh --bin PATH      # install a dformer binary built elsewhere
#   inkscape-extension/install.sh --dest DIR      # install into DIR instead
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(dirname "$here")"
bin="" dest=""
while [ $# -gt 0 ]; do
  case "$1" in
    --bin) bin="$2"; shift 2 ;;
    --dest) dest="$2"; shift 2 ;;
    -h|--help) sed -n 2,8p "$0"; exit 0 ;;
    *) echo "install.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done

if [ -z "$bin" ]; then
  command -v cargo >/dev/null || { echo "install.sh: cargo not found; install Rust from rustup.rs or pass --bin" >&2; exit 1; }
  # The path of the built binary, from cargo itself (honours CARGO_TARGET_DIR).
  bin="$(cd "$repo" && cargo build --release -p dformer-cli --message-format=json-render-diagnostics \
    | python3 -c 'import json, sys
for line in sys.stdin:
    m = json.loads(line)
    if m.get("reason") == "compiler-artifact" and m.get("executable"):
        print(m["executable"])' | tail -n 1)"
fi
[ -x "$bin" ] || { echo "install.sh: no dformer program at '$bin'" >&2; exit 1; }

if [ -z "$dest" ]; then
  user_dir=""
  if command -v inkscape >/dev/null; then user_dir="$(inkscape --user-data-directory 2>/dev/null | tail -n 1 || true)"; fi
  if [ -z "$user_dir" ]; then
    case "$(uname -s)" in
      Darwin) user_dir="$HOME/Library/Application Support/org.inkscape.Inkscape/config/inkscape" ;;
      *) user_dir="${XDG_CONFIG_HOME:-$HOME/.config}/inkscape" ;;
    esac
  fi
  dest="$user_dir/extensions/dformer"
fi

mkdir -p "$dest"
cp "$here"/dformer_*.inx "$here"/dformer_*.py "$dest"/
cp "$bin" "$dest/dformer"
chmod +x "$dest/dformer"
echo "D-former installed in $dest; restart Inkscape and look under Extensions > D-former."
