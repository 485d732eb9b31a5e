"""Figures of a growthuq campaign (tools/plot): reading results.h5 and the optional
tradeoff.csv, one module per figure family, each returning matplotlib Figures so that tests can
read back what was drawn. Headless: figures are built with matplotlib.figure.Figure (no pyplot,
no GUI backend) and saved through the Agg and PDF canvases."""
