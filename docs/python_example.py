"""The README's Python example: run from the project root as
    PYTHONPATH=build/python /usr/bin/python3 docs/python_example.py
It writes docs/images/python_example.png (in Jupyter, a cell ending in `scene` shows it)."""
import numpy as np

import ewaview

# A file, with the command line's options as keywords ('_' for '-').
engine = ewaview.Scene("../shared/data/engine/engine.nhdr", resolution=(320, 320),
                       camera_position=(420, -300, 320), camera_view_up=(0, 0, 1),
                       background=(0.12, 0.12, 0.15))
engine.transfer_function = "Inferno (colour map)"  # a preset's colours, the opacity kept
left = engine.render(shading=True)                   # uint8, shape (320, 320, 3)

# A NumPy array indexed [z, y, x] with its voxel spacing: a torus sampled by 48 slices twice as
# far apart as its rows and columns.
z, y, x = np.mgrid[-1:1:48j, -1:1:96j, -1:1:96j]
torus = np.exp(-((np.hypot(x, y) - 0.6) ** 2 + z ** 2) / 0.03).astype(np.float32)
ring = ewaview.Scene(torus, spacing=(1, 1, 2), resolution=(320, 320),
                     camera_position=(47.5, -110, 90), camera_view_up=(0, 0, 1),
                     background=(0.12, 0.12, 0.15))
ring.transfer_function = {"opacity": [[0.2, 0], [0.5, 0.05], [1, 0.6]],
                          "color": [[0.2, 0.1, 0.3, 0.9], [0.6, 0.9, 0.3, 0.3], [1, 1.0, 0.9, 0.5]]}
right = ring.render(renderer="shearwarp", preintegrated=True)

ewaview.write_png("docs/images/python_example.png", np.hstack([left, right]))
