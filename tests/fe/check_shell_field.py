"""Checks an XDMF file written by write_shell_field: well-formed XML, and every DataItem names
a dataset of the HDF5 file beside it with the dimensions it states. Prints 'ok' or the problem."""
import os
import sys
import xml.etree.ElementTree as ElementTree

import h5py

xdmf = sys.argv[1]
root = ElementTree.parse(xdmf).getroot()  # raises on malformed XML
assert root.tag == "Xdmf" and root.get("Version") == "3.0", root.attrib
grid = root.find("Domain/Grid")
topology = grid.find("Topology")
assert topology.get("TopologyType") == "Triangle"
assert grid.find("Geometry").get("GeometryType") == "XYZ"
items = root.iter("DataItem")
count = 0
for item in items:
    file_name, dataset = item.text.strip().split(":")
    with h5py.File(os.path.join(os.path.dirname(xdmf), file_name), "r") as data:
        assert dataset in data, dataset
        dims = tuple(int(n) for n in item.get("Dimensions").split())
        assert data[dataset].shape == dims, (dataset, data[dataset].shape, dims)
        assert item.get("Format") == "HDF"
    count += 1
names = sorted(a.get("Name") for a in grid.iter("Attribute"))
assert count == 2 + len(names), count
assert int(topology.get("NumberOfElements")) == int(grid.find("Topology/DataItem").get("Dimensions").split()[0])
print("ok", count, " ".join(names))
