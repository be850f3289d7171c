#!/usr/bin/env python3
"""Makes the MovingAI maps and scenarios that ship with Ringlet (planning/maps/).

The maps are drawn from a fixed seed, so running this again writes the same files. The optimal
length of every scenario is computed here with networkx (Dijkstra over the octile grid, no
corner cutting), independently of the planner that `ringlet-plan-bench check` then tests.

    python3 planning/maps/make_maps.py [--out DIR]
"""
import argparse
import math
import random
import sys
from pathlib import Path

try:
    import networkx as nx
except ImportError:  # tools/ringlet setup installs python3-networkx
    sys.exit("make_maps.py needs networkx (Debian: python3-networkx)")

SQRT2 = math.sqrt(2.0)


def rooms(w, h, rng):
    """Rooms off corridors: walls with doors, some rooms closed on three sides (dead ends)."""
    g = [['.'] * w for _ in range(h)]
    room = 25
    for y in range(0, h, room):
        for x in range(w):
            g[y][x] = '@'
    for x in range(0, w, room):
        for y in range(h):
            g[y][x] = '@'
    for ry in range(0, h, room):
        for rx in range(0, w, room):
            # Doors in the room's top and left walls, most of them; a few rooms get one door only.
            for side in ('top', 'left'):
                if rng.random() < 0.75:
                    at = rng.randrange(3, room - 5)
                    for d in range(3):
                        if side == 'top' and ry > 0:
                            g[ry][rx + at + d] = '.'
                        if side == 'left' and rx > 0:
                            g[ry + at + d][rx] = '.'
            # Clutter inside the room.
            for _ in range(rng.randrange(0, 4)):
                bx, by = rx + rng.randrange(3, room - 6), ry + rng.randrange(3, room - 6)
                for yy in range(by, by + rng.randrange(1, 4)):
                    for xx in range(bx, bx + rng.randrange(1, 5)):
                        if yy < h and xx < w:
                            g[yy][xx] = 'T'
    return g


def forest(w, h, rng):
    """A wood: clumps of trees, denser to the east, with a winding clearing."""
    g = [['.'] * w for _ in range(h)]
    for _ in range(int(w * h * 0.012)):
        cx, cy = rng.randrange(w), rng.randrange(h)
        if rng.random() > 0.35 + 0.6 * cx / w:
            continue
        r = rng.uniform(1.0, 3.5)
        for y in range(int(cy - r), int(cy + r) + 1):
            for x in range(int(cx - r), int(cx + r) + 1):
                if 0 <= x < w and 0 <= y < h and (x - cx) ** 2 + (y - cy) ** 2 <= r * r:
                    g[y][x] = 'T'
    for y in range(h):  # the clearing
        c = int(w * 0.3 + w * 0.12 * math.sin(y / 17.0))
        for x in range(c - 3, c + 4):
            if 0 <= x < w:
                g[y][x] = '.'
    return g


def maze(w, h, rng):
    """A maze of 3-cell corridors (depth-first), many dead ends."""
    g = [['@'] * w for _ in range(h)]
    cell = 4
    cw, ch = (w - 1) // cell, (h - 1) // cell
    seen = [[False] * cw for _ in range(ch)]
    stack = [(0, 0)]
    seen[0][0] = True

    def carve(cx, cy):
        for y in range(cy * cell + 1, cy * cell + cell):
            for x in range(cx * cell + 1, cx * cell + cell):
                g[y][x] = '.'

    carve(0, 0)
    while stack:
        cx, cy = stack[-1]
        nbrs = [(cx + dx, cy + dy) for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1))
                if 0 <= cx + dx < cw and 0 <= cy + dy < ch and not seen[cy + dy][cx + dx]]
        if not nbrs:
            stack.pop()
            continue
        nx_, ny_ = rng.choice(nbrs)
        seen[ny_][nx_] = True
        carve(nx_, ny_)
        # Open the wall between the two cells.
        if nx_ != cx:
            x = max(cx, nx_) * cell
            for y in range(cy * cell + 1, cy * cell + cell):
                g[y][x] = '.'
        else:
            y = max(cy, ny_) * cell
            for x in range(cx * cell + 1, cx * cell + cell):
                g[y][x] = '.'
        stack.append((nx_, ny_))
    return g


def passable(c):
    return c in '.GS'


def graph_of(g):
    h, w = len(g), len(g[0])
    G = nx.Graph()
    for y in range(h):
        for x in range(w):
            if not passable(g[y][x]):
                continue
            G.add_node((x, y))
            for dx, dy in ((1, 0), (0, 1), (1, 1), (-1, 1)):
                x2, y2 = x + dx, y + dy
                if not (0 <= x2 < w and 0 <= y2 < h and passable(g[y2][x2])):
                    continue
                if dx != 0 and dy != 0 and not (passable(g[y][x2]) and passable(g[y2][x])):
                    continue  # no corner cutting
                G.add_edge((x, y), (x2, y2), weight=SQRT2 if dx and dy else 1.0)
    return G


def write(out, name, g, problems, rng):
    h, w = len(g), len(g[0])
    (out / f'{name}.map').write_text(
        f'type octile\nheight {h}\nwidth {w}\nmap\n' + ''.join(''.join(row) + '\n' for row in g))
    G = graph_of(g)
    # The largest connected part holds the problems (a start walled off from its goal tests nothing).
    part = max(nx.connected_components(G), key=len)
    cells = sorted(part)
    lines = ['version 1']
    found = 0
    while found < problems:
        s, t = rng.choice(cells), rng.choice(cells)
        d = nx.dijkstra_path_length(G, s, t, weight='weight')
        if d < min(w, h) * 0.5:  # long routes: where replanning matters
            continue
        lines.append(f'{int(d // 4)}\t{name}.map\t{w}\t{h}\t{s[0]}\t{s[1]}\t{t[0]}\t{t[1]}\t{d:.8f}')
        found += 1
        print(f'{name}: {found}/{problems}', file=sys.stderr, end='\r')
    print(file=sys.stderr)
    (out / f'{name}.map.scen').write_text('\n'.join(lines) + '\n')


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--out', type=Path, default=Path(__file__).resolve().parent, help='where to write (default: beside this script)')
    args = ap.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    write(args.out, 'rooms200', rooms(200, 200, random.Random(1)), 40, random.Random(11))
    write(args.out, 'forest200', forest(200, 200, random.Random(2)), 40, random.Random(12))
    write(args.out, 'maze65', maze(65, 65, random.Random(3)), 30, random.Random(13))


if __name__ == '__main__':
    main()
