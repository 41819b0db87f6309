"""The bridge to the D-former geometry core: the ``dformer`` command speaking JSON.

All geometry (path parsing, arc length, normalization, connectors) happens in the Rust core;
this module only finds the ``dformer`` binary, sends it a batch of requests on stdin and reads
the answers. A request is ``{"op": <contract function>, <argument>: <value>, ...}`` and the
answer is the function's result, or ``{"error": <the core's message>}``.

The binary is looked up in this order:

1. the ``DFORMER_BIN`` environment variable (a full path, for developers and tests);
2. ``dformer`` / ``dformer.exe`` next to this file: the one bundled in the release zips
   (``bash scripts/package.sh``) or copied by ``install.sh``;
3. ``dformer`` on ``PATH``.

Every message about the program failing names the one used and where it came from.
"""

import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
EXE = "dformer.exe" if sys.platform.startswith("win") else "dformer"


class CoreError(Exception):
    """A message for the user: the core's own error text, or why the core could not run."""


def locate_binary():
    """Returns ``(path, origin)`` of the ``dformer`` binary to use, origin saying where it was
    found (for messages), or raises CoreError saying how to install it."""
    explicit = os.environ.get("DFORMER_BIN")
    if explicit:
        if os.path.isfile(explicit):
            return explicit, "set by DFORMER_BIN"
        raise CoreError(f"DFORMER_BIN is set to {explicit!r}, but there is no file there.")
    beside = os.path.join(HERE, EXE)
    if os.path.isfile(beside):
        _prepare_bundled(beside)
        return beside, "bundled with the extension"
    on_path = shutil.which("dformer")
    if on_path:
        return on_path, "found on PATH"
    raise CoreError(
        f"The D-former core program ({EXE}) was not found next to the extension ({HERE}) "
        "or on PATH. Download the D-former Inkscape zip for your system and copy its whole "
        "dformer folder into Inkscape's user extensions folder again (see the D-former README, "
        "Download and install); developers can build it with `cargo build --release -p dformer-cli`."
    )


# macOS's tool for extended attributes (a module constant so the tests can stand in for it).
XATTR = "/usr/bin/xattr"


def _prepare_bundled(path):
    """Makes the bundled binary runnable as installed by a user:

    - Inkscape's Extension Manager (Extensions > Manage Extensions, install from file) writes a
      zip's files without their permissions, so on Linux and macOS the binary arrives not
      executable: give it back the executable bits its owner may set (nothing to do on Windows);
    - on macOS, files unzipped from a download carry the com.apple.quarantine flag, and
      Gatekeeper refuses to start a quarantined program that Apple has not notarized: the user
      installed this extension on purpose, so the flag is cleared from its own bundled program
      (only that file), as `xattr -d com.apple.quarantine` would.
    Failures are ignored: running it then fails with a message that names it."""
    if os.name != "nt" and not os.access(path, os.X_OK):
        try:
            mode = os.stat(path).st_mode
            os.chmod(path, mode | ((mode & 0o444) >> 2))
        except OSError:
            pass
    if sys.platform == "darwin" and os.path.exists(XATTR):
        subprocess.run([XATTR, "-d", "com.apple.quarantine", path], capture_output=True, check=False)


def find_binary():
    """Returns the path of the ``dformer`` binary, or raises CoreError saying how to install it."""
    return locate_binary()[0]


def run_batch(requests):
    """Sends a list of requests in one process; returns the list of answers (each a result
    or ``{"error": message}``), in order."""
    if not requests:
        return []
    binary, origin = locate_binary()
    which = f"{binary} ({origin})"
    try:
        proc = subprocess.run(
            [binary, "json"],
            input=json.dumps(requests).encode("utf-8"),
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            check=False,
            timeout=120,
            # No console window flashing up on Windows for each call.
            creationflags=getattr(subprocess, "CREATE_NO_WINDOW", 0),
        )
    except (OSError, subprocess.SubprocessError) as err:
        hint = ""
        if isinstance(err, PermissionError):
            hint = " It is not marked as a program: unzip the D-former zip again, or run chmod +x on it."
        elif isinstance(err, OSError) and getattr(err, "errno", None) == 8:  # ENOEXEC
            hint = " It is not a program for this computer: download the D-former zip for your system."
        raise CoreError(f"Could not run the D-former core program {which}: {err}.{hint}") from err
    try:
        answers = json.loads(proc.stdout.decode("utf-8"))
    except ValueError as err:
        detail = proc.stderr.decode("utf-8", "replace").strip()
        raise CoreError(
            f"The D-former core program {which} gave no readable answer "
            f"(exit status {proc.returncode}). {detail}"
        ) from err
    if isinstance(answers, dict) and "error" in answers:
        # The whole batch was refused (e.g. not JSON): one message for everything.
        raise CoreError(answers["error"])
    if not isinstance(answers, list) or len(answers) != len(requests):
        raise CoreError(f"The D-former core program {which} answered {len(requests)} requests unexpectedly.")
    return answers


def call_all(requests):
    """Like run_batch, but raises CoreError with the first error message."""
    answers = run_batch(requests)
    for answer in answers:
        if isinstance(answer, dict) and "error" in answer:
            raise CoreError(answer["error"])
    return answers


def advise(text, host="inkscape"):
    """``text`` naming this host's commands: every plain phrase of the one table
    (messages/commands.json, compiled into ``dformer``) in Inkscape's words, e.g. "close the path"
    becomes "close the path (Node tool: ... Join selected nodes ...)". When the core program
    cannot be run, the plain words stay."""
    try:
        answer = run_batch([{"op": "advise", "text": text, "host": host}])[0]
    except CoreError:
        return text
    return answer if isinstance(answer, str) else text


def call(op, **args):
    """One contract function, e.g. ``call("measure", path=p)``; raises CoreError on failure."""
    request = dict(args)
    request["op"] = op
    return call_all([request])[0]
