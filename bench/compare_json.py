#!/usr/bin/env python3
"""Compares two JSON outputs of fogbench-cli (analyze/response/diagnose
--json) for speed work that may reorder additions: keys, strings, booleans
and integers must be identical; every other number within --rel (default
1e-12) relative or --abs (default 1e-15) absolute. Keys that time the run
(elapsed_s, and any named with --ignore) are skipped.

usage: bench/compare_json.py OLD.json NEW.json [--rel R] [--abs A] [--ignore KEY ...]
Exit 0 when they agree, 1 with each difference listed otherwise.
"""
import argparse
import json
import math
import sys


def walk(old, new, path, args, out):
    if isinstance(old, dict) and isinstance(new, dict):
        if sorted(old) != sorted(new):
            out.append(f'{path}: keys differ: {sorted(set(old) ^ set(new))}')
            return
        for k in old:
            if k not in args.ignore:
                walk(old[k], new[k], f'{path}.{k}', args, out)
    elif isinstance(old, list) and isinstance(new, list):
        if len(old) != len(new):
            out.append(f'{path}: {len(old)} items, now {len(new)}')
            return
        for i, (a, b) in enumerate(zip(old, new)):
            walk(a, b, f'{path}[{i}]', args, out)
    elif type(old) is float and type(new) is float:
        if old == new or (math.isnan(old) and math.isnan(new)):
            return
        if not (math.isfinite(old) and math.isfinite(new)):
            out.append(f'{path}: {old!r} -> {new!r}')
        elif not abs(old - new) <= max(args.rel * max(abs(old), abs(new)), args.abs):
            out.append(f'{path}: {old!r} -> {new!r} (rel {abs(old - new) / max(abs(old), abs(new)):.2e})')
    elif old != new or type(old) != type(new):
        out.append(f'{path}: {old!r} -> {new!r}')


def main():
    p = argparse.ArgumentParser()
    p.add_argument('old')
    p.add_argument('new')
    p.add_argument('--rel', type=float, default=1e-12)
    p.add_argument('--abs', type=float, default=1e-15)
    p.add_argument('--ignore', nargs='*', default=[])
    args = p.parse_args()
    args.ignore = set(args.ignore) | {'elapsed_s'}
    with open(args.old) as f:
        old = json.load(f)
    with open(args.new) as f:
        new = json.load(f)
    out = []
    walk(old, new, '$', args, out)
    for line in out:
        print(line)
    print(f'{len(out)} difference(s) beyond rel {args.rel:g} / abs {args.abs:g}', file=sys.stderr)
    return 1 if out else 0


if __name__ == '__main__':
    sys.exit(main())
