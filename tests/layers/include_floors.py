#!/usr/bin/env python3
"""The house drawn from the includes (docs/architecture.md, "Layers"): every
#include "renderer/..." in renderer/ goes to its own folder or to a lower
floor, never up or sideways, so the library has no circles; renderer/
includes none of app/, ui/, python/ or headless/; headless/ none of app/,
ui/ or python/; ui/ none of app/ or python/; python/ none of app/.

Run from anywhere: python3 tests/layers/include_floors.py [ROOT]. Prints each
include that breaks a rule (file:line, the include, the two floors) and exits
1 when there is one."""
import os
import re
import sys

# Lowest first. A name is a folder under renderer/ or a file at its top
# (renderer/Error.h is "Error"). One floor may hold several folders that do
# not include each other.
FLOORS = [
    ["Error", "OptionLimits"],
    ["OptionText"],
    ["io"],
    ["gl"],
    ["scene"],
    ["knobs"],
    ["metrics"],
    ["graph"],
    ["RunConfig"],
    ["ao", "lighting", "oit"],
    ["reference"],
    ["passes"],
    ["inspect"],
    ["RenderSession"],
    ["bench"],
    ["record"],
    ["study"],
]
FLOOR = {name: i for i, names in enumerate(FLOORS) for name in names}
# Top-level folders and the ones they must not include.
FORBIDDEN = {
    "renderer": ["app/", "ui/", "python/", "headless/"],
    "headless": ["app/", "ui/", "python/"],
    "ui": ["app/", "python/"],
    # The command layer is not a library: what Python shares with it is in headless/.
    "python": ["app/"],
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def unit_of(path_in_renderer):
    """The floor name of a path relative to renderer/ ('bench/X.h' -> 'bench', 'Error.h' -> 'Error')."""
    parts = path_in_renderer.split("/")
    return parts[0] if len(parts) > 1 else os.path.splitext(parts[0])[0]


def sources(root, top):
    for folder, _, files in os.walk(os.path.join(root, top)):
        for name in sorted(files):
            if name.endswith((".h", ".cpp", ".hpp")):
                yield os.path.join(folder, name)


def check(root):
    faults = []
    for top, banned in FORBIDDEN.items():
        for path in sources(root, top):
            rel = os.path.relpath(path, root)
            for number, line in enumerate(open(path, errors="replace"), 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                target = m.group(1)
                if any(target.startswith(b) for b in banned):
                    faults.append("%s:%d: %s includes %s (%s/ must not include it)" % (rel, number, top, target, top))
                if top != "renderer" or not target.startswith("renderer/"):
                    continue
                src = unit_of(os.path.relpath(path, os.path.join(root, "renderer")))
                dst = unit_of(target[len("renderer/"):])
                if src == dst:
                    continue
                for name in (src, dst):
                    if name not in FLOOR:
                        faults.append("%s:%d: '%s' has no floor in %s: add it to FLOORS and to docs/architecture.md"
                                      % (rel, number, name, os.path.basename(__file__)))
                if src in FLOOR and dst in FLOOR and FLOOR[dst] >= FLOOR[src]:
                    faults.append("%s:%d: %s (floor %d) includes %s (floor %d): only lower floors may be included"
                                  % (rel, number, src, FLOOR[src], target, FLOOR[dst]))
    return faults


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    faults = check(os.path.abspath(root))
    for f in faults:
        print(f)
    if faults:
        print("%d include(s) break the layers" % len(faults))
        return 1
    print("include floors: every include goes down (%d floors)" % len(FLOORS))
    return 0


if __name__ == "__main__":
    sys.exit(main())
