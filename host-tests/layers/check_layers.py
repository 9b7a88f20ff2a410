#!/usr/bin/env python3
"""Checks that the dependencies between Costa's layers point one way.

  od/      the object dictionary runtime: its own headers and the port interfaces only
  stack/   the services: the dictionary, its own headers, the port interfaces; no port
           implementation (costa/port/linux/, costa/port/stm32/, ...)
  port/    CAN controllers, clocks, storage: port headers only, never a stack or dictionary
           header (drivers report controller events and take bit rates through
           costa/port/can_controller_event.hpp and costa/port/can_bit_rate.hpp)
  targets/<device>/ (each directory of targets/devices.cmake): the installed headers
           (costa/...); by name only its own files, targets/' files (held to the same rule)
           and its generated NAME_od.hpp; never a port implementation but port/memory (a
           simulated device's own memory), never a path into another directory (../,
           stack/src, another device's)

and that the freestanding parts (od/, stack/, the port interfaces, the devices' directories)
include no system header beyond the freestanding ones. Prints one line per violation and exits
1 when there is any.
`--self-test` plants violations in a scratch tree and checks that each one is reported.
"""
import argparse
import pathlib
import re
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.MULTILINE)
SOURCES = ('.hpp', '.cpp', '.h', '.c')
FREESTANDING = {
    'stddef.h', 'stdint.h', 'stdbool.h', 'stdarg.h', 'limits.h', 'float.h',
    'cstddef', 'cstdint', 'climits', 'cfloat', 'cstdarg', 'limits', 'type_traits', 'new',
    'initializer_list', 'atomic',
}


def is_port_interface(header):
    """A header of the port interfaces (costa/port/NAME.hpp), not of one port."""
    parts = header.split('/')
    return len(parts) == 3 and parts[:2] == ['costa', 'port']


DEVICE = re.compile(r'^\s*costa_device\(\s*\S+\s+(\S+)\s*\)', re.MULTILINE)
GENERATED = re.compile(r'^[a-z0-9_]+_od\.hpp$')  # a dictionary's header, written by the build


def device_directories(root):
    """The directories under targets/ that hold a device (targets/devices.cmake)."""
    listing = root / 'targets' / 'devices.cmake'
    if not listing.is_file():
        return set()
    return set(DEVICE.findall(listing.read_text(encoding='utf-8')))


def device_may_include(header, path, root):
    """A device's directory: installed headers, no port implementation but port/memory; files
    by name from its own directory or targets/, or its generated dictionary header; no path
    into another directory."""
    if '..' in header.split('/'):
        return False
    if header.startswith('costa/port/'):
        return is_port_interface(header) or header.startswith('costa/port/memory/')
    if header.startswith('costa/'):
        return True
    if '/' in header:
        return False
    return ((path.parent / header).is_file() or (root / 'targets' / header).is_file()
            or GENERATED.match(header) is not None)


def rule_for(relative, devices=frozenset()):
    """(allowed include predicate (header, path, root), freestanding?) for a file, or None for
    no rule. The predicate sees every costa/ header (od/, stack/, port/) and every quoted one
    (a device's directory)."""
    parts = relative.parts
    if parts[0] == 'targets' and len(parts) > 2 and parts[1] in devices:
        return device_may_include, True
    if parts[0] == 'od' and parts[1] in ('src', 'include'):
        return (lambda h, *_: h.startswith('costa/od/') or is_port_interface(h)), True
    if parts[0] == 'stack':
        return (lambda h, *_: not h.startswith('costa/port/') or is_port_interface(h)), True
    if parts[0] == 'port':
        interface = parts[1:4] == ('include', 'costa', 'port') and len(parts) == 5
        return (lambda h, *_: h.startswith('costa/port/')), interface
    return None


def check_file(root, path, allowed, freestanding, checks_quoted, found):
    """Appends the file's violations to `found`; returns the quoted headers it includes."""
    relative = path.relative_to(root)
    text = path.read_text(encoding='utf-8', errors='replace')
    quoted = []
    for match in INCLUDE.finditer(text):
        kind, header = match.groups()
        line = text.count('\n', 0, match.start()) + 1
        crossing = header.startswith('costa/') or (checks_quoted and kind == '"')
        if crossing and not allowed(header, path, root):
            found.append(f'{relative}:{line}: includes {header} across a layer')
        elif kind == '<' and freestanding and header not in FREESTANDING:
            found.append(f'{relative}:{line}: includes <{header}>, not freestanding')
        if kind == '"':
            quoted.append(header)
    return quoted


def violations(root):
    found = []
    devices = device_directories(root)
    if (root / 'targets').is_dir() and not devices:
        found.append('targets/devices.cmake: names no device directory to check')
    shared = set()  # targets/' own headers that a device includes: held to the same rule
    for top in ('od', 'stack', 'port', 'targets'):
        for path in sorted((root / top).rglob('*')):
            if path.suffix not in SOURCES or not path.is_file():
                continue
            rule = rule_for(path.relative_to(root), devices)
            if rule is None:
                continue
            allowed, freestanding = rule
            device = top == 'targets'  # elsewhere only costa/ headers cross layers
            for header in check_file(root, path, allowed, freestanding, device, found):
                if device and '/' not in header and not (path.parent / header).is_file():
                    shared.add(header)
    checked = set()
    while shared:  # and the targets/ headers those include in turn
        header = min(shared)
        shared.discard(header)
        checked.add(header)
        path = root / 'targets' / header
        if path.is_file():
            included = check_file(root, path, device_may_include, True, True, found)
            shared.update(h for h in included if '/' not in h and h not in checked)
    return found


def self_test():
    planted = {
        'port/linux/src/driver.cpp': '#include "costa/node.hpp"\n',
        'port/include/costa/port/clock.hpp': '#include <stdio.h>\n',
        'od/src/values.cpp': '#include "costa/pdo_map.hpp"\n',
        'stack/src/service.cpp': '#include "costa/port/linux/socketcan_port.hpp"\n',
        'stack/include/costa/service.hpp': '#include <vector>\n',
        'targets/dev/dev_device.cpp': '#include "costa/port/linux/socketcan_port.hpp"\n',
        'targets/dev/dev_target.hpp': '#include <stdio.h>\n',
        'targets/dev/dev_hook.cpp': '#include "../../stack/src/internal.hpp"\n',
        'targets/dev/dev_plant.cpp': '#include "linux/local_bus.hpp"\n',
        'targets/dev/dev_quoted.cpp': '#include "string.h"\n',
        'targets/dev/dev_other.cpp': '#include "other_target.hpp"\n',
        'targets/dev/dev_dots.cpp': '#include "costa/port/memory/../linux/clock.hpp"\n',
        'targets/shared.hpp': '#include <stdio.h>\n#include "shared2.hpp"\n',
        'targets/shared2.hpp': '#include "costa/port/linux/monotonic_clock.hpp"\n',
    }
    clean = {
        'port/linux/src/ok.cpp': '#include "costa/port/can_frame.hpp"\n#include <stdio.h>\n',
        'od/src/ok.cpp': '#include "costa/od/entry.hpp"\n#include "costa/port/can_frame.hpp"\n',
        'stack/src/ok.cpp': '#include "costa/od/entry.hpp"\n#include <stdint.h>\n',
        'targets/devices.cmake': 'costa_device(dev dev)\ncosta_device(dev2 dev)\n',
        'targets/dev/ok.hpp': ('#include "costa/node.hpp"\n'
                               '#include "costa/port/memory/memory_storage.hpp"\n'
                               '#include "costa/port/can_frame.hpp"\n'
                               '#include "device_control.hpp"\n#include "dev_od.hpp"\n'
                               '#include "ok2.hpp"\n#include "shared.hpp"\n'
                               '#include <stdint.h>\n'),
        'targets/dev/ok2.hpp': '#include <stddef.h>\n',
        'targets/device_control.hpp': '#include <stdint.h>\n',
        'targets/other/other_target.hpp': '#include <stdio.h>\n',
        'targets/linux/main.cpp': ('#include "costa/port/linux/socketcan_port.hpp"\n'
                                   '#include <stdio.h>\n'),
    }
    with tempfile.TemporaryDirectory() as scratch:
        root = pathlib.Path(scratch)
        for name, text in {**planted, **clean}.items():
            (root / name).parent.mkdir(parents=True, exist_ok=True)
            (root / name).write_text(text)
        found = violations(root)
    reported = {line.split(':')[0] for line in found}
    missed = sorted(set(planted) - reported)
    wrong = sorted(reported - set(planted))
    for name in missed:
        print(f'self-test: the violation planted in {name} was not reported')
    for name in wrong:
        print(f'self-test: {name} was reported though it keeps the rules')
    with tempfile.TemporaryDirectory() as scratch:  # no device list: said, not passed over
        root = pathlib.Path(scratch)
        (root / 'targets' / 'dev').mkdir(parents=True)
        (root / 'targets' / 'dev' / 'dev_device.cpp').write_text('#include <stdio.h>\n')
        unlisted = violations(root)
    if unlisted != ['targets/devices.cmake: names no device directory to check']:
        print(f'self-test: without targets/devices.cmake it reported {unlisted}')
        return 1
    return 1 if missed or wrong else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--root', type=pathlib.Path,
                        default=pathlib.Path(__file__).resolve().parents[2])
    parser.add_argument('--self-test', action='store_true')
    arguments = parser.parse_args()
    if arguments.self_test:
        return self_test()
    found = violations(arguments.root)
    for line in found:
        print(line)
    if not found:
        print('layers: every include points down (od <- stack, port interfaces <- both, '
              'public headers <- devices)')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main())
