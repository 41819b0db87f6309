"""The prebuilt `dformer` inside each Inkscape zip is a program for its platform, checked from
the bytes of its header (binfmt.py, written from the format specifications), not by the tools
that built it: macOS universal (arm64 + x86_64, ad-hoc signed so Apple silicon runs it, linked
only to libSystem), Linux static (no loader, no shared libraries: runs on any distribution),
Windows x86_64 console program importing only DLLs that every Windows has."""

import os
import subprocess
import tempfile
import unittest
import zipfile

import binfmt
from support import artifact, version

# DLLs shipped with every Windows 10/11 (no MinGW runtime such as libgcc_s_seh-1.dll or
# libwinpthread-1.dll, which a student would not have).
WINDOWS_SYSTEM_DLLS = {"kernel32.dll", "ntdll.dll", "msvcrt.dll", "advapi32.dll", "bcrypt.dll",
                       "bcryptprimitives.dll", "userenv.dll", "ws2_32.dll", "shell32.dll", "ole32.dll",
                       "user32.dll", "secur32.dll", "synchronization.dll"}


def binary(zip_name, member):
    with zipfile.ZipFile(artifact(zip_name)) as z:
        info = z.getinfo(f"dformer/{member}")
        return z.read(info), (info.external_attr >> 16) & 0o777


class MacosBinary(unittest.TestCase):
    def test_one_universal_file_with_arm64_and_x86_64_executables(self):
        data, mode = binary("inkscape-macos.zip", "dformer")
        self.assertEqual(mode & 0o111, 0o111, f"dformer must be stored executable (mode {mode:o})")
        slices = binfmt.macho_slices(data)
        archs = sorted(binfmt.CPU_NAMES.get(cpu, hex(cpu)) for cpu, _, _ in slices)
        self.assertEqual(archs, ["arm64", "x86_64"], f"wanted a fat file with arm64 and x86_64, got {archs}")
        for cpu, off, size in slices:
            name = binfmt.CPU_NAMES[cpu]
            self.assertLessEqual(off + size, len(data), f"{name} slice runs past the end of the file")
            self.assertEqual(off % 4096, 0, f"{name} slice at {off} is not page-aligned")
            thin = binfmt.macho_thin(data, off)
            self.assertEqual(thin["cputype"], cpu, f"{name}: the slice's own header says cputype {thin['cputype']:#x}")
            self.assertEqual(thin["filetype"], binfmt.MH_EXECUTE, f"{name}: wanted MH_EXECUTE, got {thin['filetype']}")
            self.assertIn(binfmt.LC_MAIN, thin["commands"], f"{name}: no LC_MAIN entry point")
            self.assertEqual([d for d in thin["dylibs"] if not d.startswith("/usr/lib/")], [],
                             f"{name}: links libraries a Mac does not have: {thin['dylibs']}")
            self.assertIn("/usr/lib/libSystem.B.dylib", thin["dylibs"], name)
            self.assertIsNotNone(thin["minos"], f"{name}: no LC_BUILD_VERSION (minimum macOS)")
            major, minor = map(int, thin["minos"].split("."))
            self.assertLessEqual((major, minor), (11, 0), f"{name}: needs macOS {thin['minos']}, wanted 11.0 (Big Sur) or older")
            if cpu == binfmt.CPU_TYPE_ARM64:
                # Apple silicon kills unsigned arm64 code: the linker must leave an ad-hoc signature.
                self.assertIn(binfmt.LC_CODE_SIGNATURE, thin["commands"], "arm64 slice has no code signature")
            print(f"macOS {name}: {size} bytes at {off}, minimum macOS {thin['minos']}, links {thin['dylibs']}")


class LinuxBinary(unittest.TestCase):
    def test_static_x86_64_executable_that_prints_the_version(self):
        data, mode = binary("inkscape-linux-x86_64.zip", "dformer")
        self.assertEqual(mode & 0o111, 0o111, f"dformer must be stored executable (mode {mode:o})")
        elf = binfmt.elf_info(data)
        self.assertEqual(elf["machine"], 62, "EM_X86_64")
        self.assertFalse(elf["interp"], "asks for a dynamic loader (PT_INTERP): not static")
        self.assertEqual(elf["needed"], 0, "needs shared libraries (DT_NEEDED): not static")
        with tempfile.TemporaryDirectory() as tmp:
            exe = os.path.join(tmp, "dformer")
            with open(exe, "wb") as fh:
                fh.write(data)
            os.chmod(exe, 0o755)
            out = subprocess.run([exe, "--version"], capture_output=True, text=True, check=True).stdout.strip()
        self.assertEqual(out, f"dformer {version()}")


class WindowsBinary(unittest.TestCase):
    def test_x86_64_console_program_importing_only_system_dlls(self):
        data, _ = binary("inkscape-windows-x86_64.zip", "dformer.exe")
        pe = binfmt.pe_info(data)
        self.assertEqual(pe["machine"], 0x8664, "IMAGE_FILE_MACHINE_AMD64")
        self.assertEqual(pe["subsystem"], 3, "IMAGE_SUBSYSTEM_WINDOWS_CUI (console: stdin/stdout for the bridge)")
        dlls = {d.lower() for d in pe["dlls"]}
        extra = sorted(d for d in dlls if d not in WINDOWS_SYSTEM_DLLS and not d.startswith("api-ms-win-"))
        self.assertEqual(extra, [], f"imports DLLs a Windows PC does not have: {extra} (all: {sorted(dlls)})")


if __name__ == "__main__":
    unittest.main()
