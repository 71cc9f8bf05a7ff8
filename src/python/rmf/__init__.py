"""rarefiedMultiphaseFoam post-processing and test helpers (run on /usr/bin/python3)."""
