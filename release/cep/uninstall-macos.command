#!/bin/bash
# D-former for Adobe Illustrator: removes the panel installed by install-macos.command.
# PlayerDebugMode is left as it is: other unsigned panels may need it
# (to reset it: defaults delete com.adobe.CSXS.N PlayerDebugMode, N = 8 to 12).
set -euo pipefail
dest="$HOME/Library/Application Support/Adobe/CEP/extensions/com.dformer.panel"
if [ -d "$dest" ]; then
  rm -rf "$dest"
  echo "D-former is removed from $dest. Restart Illustrator."
else
  echo "D-former is not installed for this user (no folder $dest)."
fi
echo "You can close this window."
