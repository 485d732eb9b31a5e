#!/usr/bin/python3
"""Compares two results.h5 files value for value: the same groups, datasets and attributes, every
number bit-identical (NaN equal to NaN). The attributes named with --ignore (default:
command_line, which holds the output directory) are left out. HDF5 stores modification times,
so two files with identical contents differ as bytes; this compares what h5py reads.
Usage: compare_results_h5.py A.h5 B.h5 [--ignore NAME ...]. Exits 0 when identical, 1 (with the
first difference) otherwise."""
import argparse
import sys

import h5py
import numpy as np


def same_values(a, b):
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype != b.dtype or a.shape != b.shape:
        return False
    if a.dtype.kind == "f":
        # bit for bit: NaN equals NaN, and -0.0 differs from 0.0
        return a.tobytes() == b.tobytes()
    if a.dtype.names:
        return all(same_values(a[name], b[name]) for name in a.dtype.names)
    return np.array_equal(a, b)


def dimension_links(node, name):
    """The dimension-scale bookkeeping HDF5 keeps as object references (addresses in the file):
    DIMENSION_LIST of a dataset (its scales per axis), REFERENCE_LIST of a scale (the datasets
    attached and their axes), as the paths they point to, which is what must agree."""
    value = node.attrs[name]
    if name == "DIMENSION_LIST":
        return [[node.file[ref].name for ref in axis] for axis in value]
    return sorted((node.file[row[0]].name, int(row[1])) for row in value)


def compare(a, b, path, ignore):
    for name in sorted(set(a.attrs) | set(b.attrs)):
        if name in ignore:
            continue
        if name not in a.attrs or name not in b.attrs:
            return f"{path}: attribute {name} only in one file"
        if name in ("DIMENSION_LIST", "REFERENCE_LIST"):
            if dimension_links(a, name) != dimension_links(b, name):
                return f"{path}: attribute {name} differs"
        elif not same_values(a.attrs[name], b.attrs[name]):
            return f"{path}: attribute {name} differs"
    if isinstance(a, h5py.Dataset):
        return None if same_values(a[()], b[()]) else f"{path}: values differ"
    if sorted(a.keys()) != sorted(b.keys()):
        return f"{path}: members differ: {sorted(a.keys())} vs {sorted(b.keys())}"
    for key in sorted(a.keys()):
        difference = compare(a[key], b[key], f"{path.rstrip('/')}/{key}", ignore)
        if difference:
            return difference
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("--ignore", nargs="*", default=["command_line"])
    args = parser.parse_args()
    with h5py.File(args.a, "r") as a, h5py.File(args.b, "r") as b:
        difference = compare(a, b, "/", set(args.ignore))
    if difference:
        print("results differ: " + difference)
        return 1
    print("results identical")
    return 0


if __name__ == "__main__":
    sys.exit(main())
