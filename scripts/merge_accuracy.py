#!/usr/bin/env python3
"""Merges pf_accuracy JSON files of one grid size (scripts/sweep_accuracy.sh writes one per
configuration) into one, in the order given.

usage: scripts/merge_accuracy.py OUT.json IN.json [IN.json ...]
"""
import json
import sys


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    merged = None
    for path in sys.argv[2:]:
        with open(path) as f:
            data = json.load(f)
        if merged is None:
            merged = data
            continue
        if data["cells"] != merged["cells"]:
            sys.exit(f"{path}: {data['cells']} cells, the first file has {merged['cells']}")
        merged["results"].extend(data["results"])
    with open(sys.argv[1], "w") as f:
        json.dump(merged, f, indent=1)
    print(f"{sys.argv[1]}: {len(merged['results'])} results")


if __name__ == "__main__":
    main()
