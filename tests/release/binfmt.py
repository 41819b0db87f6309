"""Readers of executable headers, written from the formats' specifications and not from any
build tool: Mach-O (Apple's <mach-o/loader.h> and <mach-o/fat.h>), ELF (the System V gABI) and
PE/COFF (Microsoft's PE format). Used to check the release binaries without trusting the tools
that made them."""

import struct

# <mach-o/fat.h>: the fat header and its fat_arch records are big-endian.
FAT_MAGIC = 0xCAFEBABE
FAT_MAGIC_64 = 0xCAFEBABF
# <mach-o/loader.h>: a 64-bit thin file starts with MH_MAGIC_64 in the file's own byte order.
MH_MAGIC_64 = 0xFEEDFACF
CPU_ARCH_ABI64 = 0x01000000
CPU_TYPE_X86_64 = 7 | CPU_ARCH_ABI64
CPU_TYPE_ARM64 = 12 | CPU_ARCH_ABI64
CPU_NAMES = {CPU_TYPE_X86_64: "x86_64", CPU_TYPE_ARM64: "arm64"}
MH_EXECUTE = 2
LC_REQ_DYLD = 0x80000000
LC_LOAD_DYLIB = 0x0C
LC_CODE_SIGNATURE = 0x1D
LC_BUILD_VERSION = 0x32
LC_MAIN = 0x28 | LC_REQ_DYLD


def macho_slices(data):
    """Returns [(cputype, offset, size)] for a fat (universal) file, or one slice for a thin one."""
    (magic,) = struct.unpack_from(">I", data, 0)
    if magic in (FAT_MAGIC, FAT_MAGIC_64):
        (n,) = struct.unpack_from(">I", data, 4)
        slices = []
        for i in range(n):
            if magic == FAT_MAGIC:  # cputype, cpusubtype, offset, size, align: 5 x uint32
                cpu, _sub, off, size, _align = struct.unpack_from(">iiIII", data, 8 + 20 * i)
            else:  # fat_arch_64: cputype, cpusubtype, offset (u64), size (u64), align, reserved
                cpu, _sub, off, size, _align, _res = struct.unpack_from(">iiQQII", data, 8 + 32 * i)
            slices.append((cpu, off, size))
        return slices
    thin = macho_thin(data)
    return [(thin["cputype"], 0, len(data))]


def macho_thin(data, offset=0):
    """Reads a thin 64-bit little-endian Mach-O at offset: its header fields and load commands."""
    magic, cputype, _sub, filetype, ncmds, sizeofcmds, _flags, _res = struct.unpack_from("<IiiIIIII", data, offset)
    if magic != MH_MAGIC_64:
        raise ValueError(f"no 64-bit little-endian Mach-O header at {offset}: magic {magic:#x}")
    commands, dylibs, minos = [], [], None
    at = offset + 32  # sizeof(struct mach_header_64)
    for _ in range(ncmds):
        cmd, size = struct.unpack_from("<II", data, at)
        commands.append(cmd)
        if cmd == LC_LOAD_DYLIB:  # dylib_command: name offset (lc_str) first
            (name_off,) = struct.unpack_from("<I", data, at + 8)
            dylibs.append(data[at + name_off: at + size].split(b"\0", 1)[0].decode())
        elif cmd == LC_BUILD_VERSION:  # platform, minos (xxxx.yy.zz nibbles)
            _platform, v = struct.unpack_from("<II", data, at + 8)
            minos = f"{v >> 16}.{(v >> 8) & 0xFF}"
        at += size
    if at - offset - 32 != sizeofcmds:
        raise ValueError("load commands do not add up to sizeofcmds")
    return {"cputype": cputype, "filetype": filetype, "commands": commands, "dylibs": dylibs, "minos": minos}


def elf_info(data):
    """Class, machine, and whether the ELF file asks for a dynamic loader (PT_INTERP) or
    shared libraries (DT_NEEDED in PT_DYNAMIC)."""
    if data[:4] != b"\x7fELF":
        raise ValueError("not an ELF file")
    if data[4] != 2 or data[5] != 1:
        raise ValueError("not a 64-bit little-endian ELF file")
    e_type, e_machine = struct.unpack_from("<HH", data, 16)
    (e_phoff,) = struct.unpack_from("<Q", data, 32)
    e_phentsize, e_phnum = struct.unpack_from("<HH", data, 54)
    interp, needed = False, 0
    for i in range(e_phnum):
        p_type, _flags, p_offset, _vaddr, _paddr, p_filesz = struct.unpack_from("<IIQQQQ", data, e_phoff + i * e_phentsize)
        if p_type == 3:  # PT_INTERP
            interp = True
        elif p_type == 2:  # PT_DYNAMIC: Elf64_Dyn entries (d_tag, d_val)
            for j in range(0, p_filesz, 16):
                tag, _val = struct.unpack_from("<qQ", data, p_offset + j)
                if tag == 0:
                    break
                if tag == 1:  # DT_NEEDED
                    needed += 1
    return {"type": e_type, "machine": e_machine, "interp": interp, "needed": needed}


def pe_info(data):
    """Machine, subsystem and imported DLL names of a PE32+ executable."""
    if data[:2] != b"MZ":
        raise ValueError("no MZ header")
    (pe,) = struct.unpack_from("<I", data, 0x3C)
    if data[pe: pe + 4] != b"PE\0\0":
        raise ValueError("no PE signature")
    machine, nsections, _t, _sym, _nsym, opt_size, _chars = struct.unpack_from("<HHIIIHH", data, pe + 4)
    opt = pe + 24
    (magic,) = struct.unpack_from("<H", data, opt)
    if magic != 0x20B:
        raise ValueError("not PE32+")
    (subsystem,) = struct.unpack_from("<H", data, opt + 68)
    import_rva, _import_size = struct.unpack_from("<II", data, opt + 112 + 8)  # data directory 1
    sections = []
    for i in range(nsections):
        s = opt + opt_size + 40 * i
        vsize, vaddr, rawsize, rawptr = struct.unpack_from("<IIII", data, s + 8)
        sections.append((vaddr, max(vsize, rawsize), rawptr))

    def at(rva):
        for vaddr, size, rawptr in sections:
            if vaddr <= rva < vaddr + size:
                return rawptr + rva - vaddr
        raise ValueError(f"RVA {rva:#x} is in no section")

    dlls = []
    d = at(import_rva)
    while True:
        _ilt, _ts, _fwd, name_rva, iat = struct.unpack_from("<IIIII", data, d)
        if name_rva == 0 and iat == 0:
            break
        n = at(name_rva)
        dlls.append(data[n: data.index(b"\0", n)].decode())
        d += 20
    return {"machine": machine, "subsystem": subsystem, "dlls": dlls}
