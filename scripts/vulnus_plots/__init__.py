"""Plots and tables of vulnus run directories (used by scripts/plot-wound and scripts/study).

Needs Debian's python3-numpy, python3-matplotlib and python3-h5py (scripts/setup).
"""
