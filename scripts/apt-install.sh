#!/usr/bin/env bash
# Installs the named Debian packages (without recommends), as root or through sudo; used by
# setup.sh and setup-release.sh for whatever they found missing. Usage: apt-install.sh PKG...
set -euo pipefail
[ $# -gt 0 ] || exit 0
printf '\033[1msetup:\033[0m installing %s from Debian\n' "$*" >&2
sudo_cmd=""
[ "$(id -u)" = 0 ] || sudo_cmd="sudo"
$sudo_cmd apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "$@" >/dev/null
