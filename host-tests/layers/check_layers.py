#!/usr/bin/env python3
"""Checks that the dependencies between Costa's layers point one way.

  od/      the object dictionary runtime: its own headers and the port interfaces only
  stack/   the services: the dictionary, its own headers, the port interfaces; no port
           implementation (costa/port/linux/, costa/port/stm32/, ...)
  port/    CAN controllers, clocks, storage: port headers only, never a stack or dictionary
           header (drivers report controller events and take bit rates through
           costa/port/can_controller_event.hpp and costa/port/can_bit_rate.hpp)

and that the freestanding parts (od/, stack/, the port interfaces) include no system header
beyond the freestanding ones. Prints one line per violation and exits 1 when there is any.
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


def rule_for(relative):
    """(allowed costa include predicate, freestanding?) for a file, or None for no rule."""
    parts = relative.parts
    if parts[0] == 'od' and parts[1] in ('src', 'include'):
        return (lambda h: h.startswith('costa/od/') or is_port_interface(h)), True
    if parts[0] == 'stack':
        return (lambda h: not h.startswith('costa/port/') or is_port_interface(h)), True
    if parts[0] == 'port':
        interface = parts[1:4] == ('include', 'costa', 'port') and len(parts) == 5
        return (lambda h: h.startswith('costa/port/')), interface
    return None


def violations(root):
    found = []
    for top in ('od', 'stack', 'port'):
        for path in sorted((root / top).rglob('*')):
            if path.suffix not in SOURCES or not path.is_file():
                continue
            relative = path.relative_to(root)
            rule = rule_for(relative)
            if rule is None:
                continue
            allowed, freestanding = rule
            text = path.read_text(encoding='utf-8', errors='replace')
            for match in INCLUDE.finditer(text):
                kind, header = match.groups()
                line = text.count('\n', 0, match.start()) + 1
                if header.startswith('costa/') and not allowed(header):
                    found.append(f'{relative}:{line}: includes {header} across a layer')
                elif kind == '<' and freestanding and header not in FREESTANDING:
                    found.append(f'{relative}:{line}: includes <{header}>, not freestanding')
    return found


def self_test():
    planted = {
        'port/linux/src/driver.cpp': '#include "costa/node.hpp"\n',
        'port/include/costa/port/clock.hpp': '#include <stdio.h>\n',
        'od/src/values.cpp': '#include "costa/pdo_map.hpp"\n',
        'stack/src/service.cpp': '#include "costa/port/linux/socketcan_port.hpp"\n',
        'stack/include/costa/service.hpp': '#include <vector>\n',
    }
    clean = {
        'port/linux/src/ok.cpp': '#include "costa/port/can_frame.hpp"\n#include <stdio.h>\n',
        'od/src/ok.cpp': '#include "costa/od/entry.hpp"\n#include "costa/port/can_frame.hpp"\n',
        'stack/src/ok.cpp': '#include "costa/od/entry.hpp"\n#include <stdint.h>\n',
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
        print('layers: every include points down (od <- stack, port interfaces <- both)')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main())
