#!/bin/bash
# D-former for Adobe Illustrator: installs the panel for this user on macOS.
# Double-click this file in Finder (the first time: right-click it, choose Open, then Open again).
# It copies com.dformer.panel into ~/Library/Application Support/Adobe/CEP/extensions and sets
# PlayerDebugMode = "1" for CSXS 8 to 12 (CEP 8 to 12), which lets Illustrator load a panel
# that is not signed by Adobe's ZXPSignCmd. Nothing else is changed.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
id=com.dformer.panel
src="$here/$id"
extensions="$HOME/Library/Application Support/Adobe/CEP/extensions"
dest="$extensions/$id"

if [ ! -f "$src/CSXS/manifest.xml" ]; then
  echo "D-former: the folder $id is not next to this installer ($here)."
  echo "Unzip the whole D-former Illustrator zip first, then double-click install-macos.command inside it."
  exit 1
fi

mkdir -p "$extensions"
rm -rf "$dest"
cp -R "$src" "$dest"
# Files unzipped from a download carry macOS's quarantine flag; the panel's files do not need it.
xattr -dr com.apple.quarantine "$dest" 2>/dev/null || true

for version in 8 9 10 11 12; do
  defaults write "com.adobe.CSXS.$version" PlayerDebugMode -string 1
done

echo "D-former is installed in:"
echo "  $dest"
echo "Restart Illustrator, then open Window > Extensions (Legacy) > D-former."
echo "You can close this window."
