#!/usr/bin/env python3
"""Writes the dictionaries of the hot-path measurements (checked in beside this script).

    python3 host-tests/benchmarks/write_eds.py     # rewrites the three files below

The communication objects are those of CANopenNode's example dictionary (CiA 301), with its
defaults, so that Costa's figures can be set beside CANopenNode's for the same dictionary:

footprint_a.eds  0x1000..0x1019, SDO server and client, 4 RPDOs and 4 TPDOs (all invalid,
                 nothing mapped). Firmware image costa-footprint-a: no optional service.
footprint_b.eds  footprint_a.eds plus guard time and life time factor (0x100C, 0x100D).
                 Firmware image costa-footprint-b: all five optional services.
hot_paths.eds    footprint_a.eds plus what the measured operations use: 0x2000 (2 x UNSIGNED32),
                 0x2001 (8 x UNSIGNED8), 0x2002 (VISIBLE_STRING, 20 characters), 0x2003
                 (8 x UNSIGNED32); RPDO1 on 0x201 -> 0x2000:01..02 and RPDO2 on 0x301 ->
                 0x2001:01..08, both type 254; TPDO1..4 on 0x181..0x481, type 1 (every SYNC),
                 two UNSIGNED32 of 0x2003 each; 0x1017 = 0.
"""
import os

UNSIGNED8, UNSIGNED16, UNSIGNED32, VISIBLE_STRING = 0x5, 0x6, 0x7, 0x9
VAR, ARRAY, RECORD = 0x7, 0x8, 0x9


def entry(name, data_type, access, default=0, mappable=False, length=None):
    return (name, data_type, access, default, mappable, length)


def count(name, value, access="const"):
    return entry(name, UNSIGNED8, access, value)


def communication_objects(guarding):
    """(index, name, object type, {sub-index: entry}) of the CiA 301 area."""
    objects = [
        (0x1000, "Device type", VAR, {0: entry("Device type", UNSIGNED32, "ro", "0x00000000")}),
        (0x1001, "Error register", VAR,
         {0: entry("Error register", UNSIGNED8, "ro", 0, mappable=True)}),
        (0x1003, "Pre-defined error field", ARRAY,
         {0: count("Number of errors", 0, "rw"),
          **{n: entry(f"Standard error field {n}", UNSIGNED32, "ro") for n in range(1, 17)}}),
        (0x1005, "COB-ID SYNC", VAR, {0: entry("COB-ID SYNC", UNSIGNED32, "rw", "0x00000080")}),
        (0x1006, "Communication cycle period", VAR,
         {0: entry("Communication cycle period", UNSIGNED32, "rw")}),
        (0x1007, "Synchronous window length", VAR,
         {0: entry("Synchronous window length", UNSIGNED32, "rw")}),
    ]
    if guarding:
        objects += [
            (0x100C, "Guard time", VAR, {0: entry("Guard time", UNSIGNED16, "rw")}),
            (0x100D, "Life time factor", VAR, {0: entry("Life time factor", UNSIGNED8, "rw")}),
        ]
    for index, name in ((0x1010, "Store parameters"), (0x1011, "Restore default parameters")):
        subs = {0: count("Highest sub-index supported", 4)}
        subs.update({n: entry(f"{name} {n}", UNSIGNED32, "rw", "0x00000001") for n in range(1, 5)})
        objects.append((index, name, ARRAY, subs))
    objects += [
        (0x1012, "COB-ID TIME", VAR, {0: entry("COB-ID TIME", UNSIGNED32, "rw", "0x00000100")}),
        (0x1014, "COB-ID EMCY", VAR, {0: entry("COB-ID EMCY", UNSIGNED32, "rw", "$NODEID+0x80")}),
        (0x1015, "Inhibit time EMCY", VAR, {0: entry("Inhibit time EMCY", UNSIGNED16, "rw")}),
        (0x1016, "Consumer heartbeat time", ARRAY,
         {0: count("Highest sub-index supported", 8),
          **{n: entry(f"Consumer heartbeat time {n}", UNSIGNED32, "rw") for n in range(1, 9)}}),
        (0x1017, "Producer heartbeat time", VAR,
         {0: entry("Producer heartbeat time", UNSIGNED16, "rw")}),
        (0x1018, "Identity object", RECORD,
         {0: count("Highest sub-index supported", 4),
          1: entry("Vendor-ID", UNSIGNED32, "ro"), 2: entry("Product code", UNSIGNED32, "ro"),
          3: entry("Revision number", UNSIGNED32, "ro"),
          4: entry("Serial number", UNSIGNED32, "ro")}),
        (0x1019, "Synchronous counter overflow value", VAR,
         {0: entry("Synchronous counter overflow value", UNSIGNED8, "rw")}),
        (0x1200, "SDO server parameter", RECORD,
         {0: count("Highest sub-index supported", 2),
          1: entry("COB-ID client to server", UNSIGNED32, "ro", "$NODEID+0x600", mappable=True),
          2: entry("COB-ID server to client", UNSIGNED32, "ro", "$NODEID+0x580", mappable=True)}),
        (0x1280, "SDO client parameter", RECORD,
         {0: count("Highest sub-index supported", 3),
          1: entry("COB-ID client to server", UNSIGNED32, "rw", "0x80000000", mappable=True),
          2: entry("COB-ID server to client", UNSIGNED32, "rw", "0x80000000", mappable=True),
          3: entry("Node-ID of the SDO server", UNSIGNED8, "rw", 1)}),
    ]
    return objects


def pdo_objects(hot_paths):
    objects = []
    for n in range(4):
        base = 0x200 + 0x100 * n
        valid = hot_paths and n < 2
        cob = f"$NODEID+0x{base:X}" if valid else f"$NODEID+0x{0x80000000 + base:X}"
        objects.append((0x1400 + n, f"RPDO communication parameter {n + 1}", RECORD, {
            0: count("Highest sub-index supported", 5),
            1: entry("COB-ID used by RPDO", UNSIGNED32, "rw", cob),
            2: entry("Transmission type", UNSIGNED8, "rw", 254),
            5: entry("Event timer", UNSIGNED16, "rw")}))
    for n in range(4):
        mapped = []
        if hot_paths and n == 0:
            mapped = [0x20000120, 0x20000220]
        elif hot_paths and n == 1:
            mapped = [0x20010008 | (sub << 8) for sub in range(1, 9)]
        objects.append((0x1600 + n, f"RPDO mapping parameter {n + 1}", RECORD,
                        mapping(mapped)))
    for n in range(4):
        base = 0x180 + 0x100 * n
        # Bit 30 (no RTR) always; bit 31 (invalid) unless measured.
        cob = f"$NODEID+0x{(0x40000000 if hot_paths else 0xC0000000) + base:X}"
        objects.append((0x1800 + n, f"TPDO communication parameter {n + 1}", RECORD, {
            0: count("Highest sub-index supported", 6),
            1: entry("COB-ID used by TPDO", UNSIGNED32, "rw", cob),
            2: entry("Transmission type", UNSIGNED8, "rw", 1 if hot_paths else 254),
            3: entry("Inhibit time", UNSIGNED16, "rw"),
            5: entry("Event timer", UNSIGNED16, "rw"),
            6: entry("SYNC start value", UNSIGNED8, "rw")}))
    for n in range(4):
        mapped = [0x20030020 | ((2 * n + k) << 8) for k in (1, 2)] if hot_paths else []
        objects.append((0x1A00 + n, f"TPDO mapping parameter {n + 1}", RECORD,
                        mapping(mapped)))
    return objects


def mapping(mapped):
    subs = {0: count("Number of mapped objects", len(mapped), "rw")}
    for sub in range(1, 9):
        value = mapped[sub - 1] if sub <= len(mapped) else 0
        subs[sub] = entry(f"Mapped object {sub}", UNSIGNED32, "rw", f"0x{value:08X}")
    return subs


def measured_objects():
    return [
        (0x2000, "Received 2 x u32", ARRAY,
         {0: count("Highest sub-index supported", 2),
          **{n: entry(f"Word {n}", UNSIGNED32, "rw", 0, mappable=True) for n in (1, 2)}}),
        (0x2001, "Received 8 x u8", ARRAY,
         {0: count("Highest sub-index supported", 8),
          **{n: entry(f"Byte {n}", UNSIGNED8, "rw", 0, mappable=True) for n in range(1, 9)}}),
        (0x2002, "Label", VAR,
         {0: entry("Label", VISIBLE_STRING, "rw", "ABCDEFGHIJKLMNOPQRST", length=20)}),
        (0x2003, "Transmitted 8 x u32", ARRAY,
         {0: count("Highest sub-index supported", 8),
          **{n: entry(f"Word {n}", UNSIGNED32, "rw", f"0x{0x11111111 * n:08X}", mappable=True)
             for n in range(1, 9)}}),
    ]


def entry_keys(e):
    name, data_type, access, default, mappable, length = e
    keys = [f"ParameterName={name}", f"DataType=0x{data_type:04X}", f"AccessType={access}",
            f"DefaultValue={default}", f"PDOMapping={1 if mappable else 0}"]
    if length is not None:
        keys.append(f"CostaStringLength={length}")
    return keys


def render(file_name, product, description, objects):
    lines = [f"; {description}", "; Written by write_eds.py (same directory): edit that, not this.",
             "", "[FileInfo]", f"FileName={file_name}", "FileVersion=1", "FileRevision=0",
             "EDSVersion=4.0", f"Description={description}", "",
             "[DeviceInfo]", "VendorName=Costa", f"ProductName={product}", "NrOfRXPDO=4",
             "NrOfTXPDO=4", "LSS_Supported=0", ""]
    indices = sorted(index for index, _, _, _ in objects)
    lists = (("MandatoryObjects", [i for i in indices if i in (0x1000, 0x1001, 0x1018)]),
             ("OptionalObjects", [i for i in indices if i < 0x2000 and
                                  i not in (0x1000, 0x1001, 0x1018)]),
             ("ManufacturerObjects", [i for i in indices if i >= 0x2000]))
    for section, listed in lists:
        lines += [f"[{section}]", f"SupportedObjects={len(listed)}"]
        lines += [f"{n}=0x{index:04X}" for n, index in enumerate(listed, 1)]
        lines.append("")
    for index, name, object_type, subs in sorted(objects):
        if object_type == VAR:
            lines += [f"[{index:04X}]", "ObjectType=0x7"] + entry_keys(subs[0]) + [""]
            continue
        lines += [f"[{index:04X}]", f"ParameterName={name}", f"ObjectType=0x{object_type:X}",
                  f"SubNumber={len(subs)}", ""]
        for sub, e in sorted(subs.items()):
            lines += [f"[{index:04X}sub{sub:X}]"] + entry_keys(e) + [""]
    return "\n".join(lines)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    files = {
        "footprint_a.eds": ("footprint A", "Hot-path dictionary, footprint configuration A",
                            communication_objects(False) + pdo_objects(False)),
        "footprint_b.eds": ("footprint B", "Hot-path dictionary, footprint configuration B",
                            communication_objects(True) + pdo_objects(False)),
        "hot_paths.eds": ("hot paths", "Hot-path dictionary of the measured operations",
                          communication_objects(False) + pdo_objects(True) + measured_objects()),
    }
    for file_name, (product, description, objects) in files.items():
        with open(os.path.join(here, file_name), "w", encoding="ascii") as out:
            out.write(render(file_name, product, description, objects))


if __name__ == "__main__":
    main()
