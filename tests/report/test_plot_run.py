#!/usr/bin/python3
"""scripts/plot_run.py on made-up inputs: the cylinders' colours (red counter-clockwise, blue
clockwise, deeper for a larger |omega~|), their equal x and y scales and labels inside the
picture; the composite figure of a made-up shear-cell run, with a snapshot given and one
missing.

    /usr/bin/python3 tests/report/test_plot_run.py SCRIPTS_DIR   (ctest runs it)

Exit status 77 (ctest: skipped) without numpy and matplotlib.
"""
import json
import os
import struct
import sys
import tempfile
import unittest

sys.path.insert(0, sys.argv.pop(1) if len(sys.argv) > 1 else "scripts")
try:
    import numpy as np
    import plot_run as pr
    import matplotlib.pyplot as plt
except ImportError as e:
    print(f"skipped: {e}")
    sys.exit(77)


def png_size(path):
    """(width, height) from the PNG's IHDR chunk."""
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR", path
    return struct.unpack(">II", head[16:24])


class Cylinders(unittest.TestCase):
    def test_red_counter_clockwise_blue_clockwise_deeper_when_faster(self):
        red_slow, red_fast = pr.rotation_colour(1, 0.2, 1.0), pr.rotation_colour(1, 1.0, 1.0)
        blue = pr.rotation_colour(-1, -0.7, 1.0)
        self.assertGreater(red_fast[0], red_fast[2])  # red over blue
        self.assertGreater(blue[2], blue[0])
        self.assertLess(sum(red_fast[:3]), sum(red_slow[:3]))  # darker
        self.assertEqual(pr.rotation_colour(np.nan, 0.5, 1.0), "grey")

    def test_circles_drawn_as_circles_and_every_label_inside(self):
        x, y = np.array([2.0, 14.0, 30.0]), np.array([1.0, 3.0, 2.0])
        t0, h = np.array([0.0, 2.0, 5.0]), np.array([3.0, 4.0, 2.0])
        d, w, sign = np.array([1.0, 2.0, 1.5]), np.array([0.7, -0.3, np.nan]), np.array([1, -1, 1])
        fig = pr.cylinders_figure(x, y, t0, h, d, w, sign)
        ax = fig.axes[0]
        aspect = ax.get_box_aspect()
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        self.assertAlmostEqual(aspect[0] / aspect[1], (x1 - x0) / (y1 - y0), places=6)
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        box = fig.bbox
        for label in (ax.xaxis.label, ax.yaxis.label, ax.zaxis.label):
            extent = label.get_window_extent(renderer)
            self.assertTrue(box.x0 <= extent.x0 and extent.x1 <= box.x1 and
                            box.y0 <= extent.y0 and extent.y1 <= box.y1,
                            f"'{label.get_text()}' at {extent} outside {box}")
        self.assertEqual(fig.get_size_inches().tolist(), [8.0, 6.0])
        plt.close(fig)


def made_up_run(folder):
    """A shear-cell run folder as softgrain run and analyze leave it, reduced to what the
    composite reads."""
    analysis = os.path.join(folder, "analysis")
    os.makedirs(analysis)
    t = np.linspace(0.0, 4.0, 81)
    with open(os.path.join(folder, "series.csv"), "w") as f:
        f.write("time,top_fx,top_fy,bottom_fx,bottom_fy\n")
        for v in t:
            f.write(f"{v},{-0.5},{6.0},{0.5},{-6.0}\n")  # mu = Ft / Fn = 0.5 / 6
    with open(os.path.join(analysis, "profiles.csv"), "w") as f:
        f.write("y_center,vx_mean,vx_std,vy_mean,vy_std\n")
        for y in np.linspace(0.5, 2.5, 5):
            f.write(f"{y},{(y - 1.5) / 2},0.05,0.0,0.01\n")
    q = {"mu": 1 / 12, "mu_error": 0.004, "window_begin": 2.5, "window_end": 4.0,
         "top_mu": 1 / 12, "bottom_mu": 1 / 12, "stiffness_tilde": 1.0,
         "cohesion_tilde": -1.0, "viscosity_tilde": -2.31}
    summary = {"format": pr.SUMMARY_FORMAT, "version": pr.SUMMARY_VERSION, "run": folder,
               "softgrain": {"version": "9.9.9", "commit": "0123456789ab"},
               "quantities": {k: {"value": v} for k, v in q.items()},
               "campaign": {"requested": {"stiffness_tilde": 1.0, "cohesion_tilde": -1.0,
                                          "viscosity_tilde": -2.5}}}
    with open(os.path.join(analysis, "summary.json"), "w") as f:
        json.dump(summary, f)
    snapshot = os.path.join(folder, "velocity.png")
    plt.imsave(snapshot, np.random.default_rng(1).random((50, 150)))
    return snapshot


class Composite(unittest.TestCase):
    def test_the_composite_with_a_given_and_a_missing_snapshot(self):
        with tempfile.TemporaryDirectory() as folder:
            snapshot = made_up_run(folder)
            status = pr.main(["plot_run.py", folder, "--snapshot", f"velocity_x={snapshot}",
                              "--snapshot-note", "no strain_rate snapshot: made up"])
            self.assertEqual(status, 0)
            png = os.path.join(folder, "analysis", "composite.png")
            self.assertEqual(png_size(png), (1760, 1100))
            with open(png, "rb") as f:
                self.assertIn(b"Software\0softgrain 9.9.9 (commit 0123456789ab)", f.read())
            self.assertFalse(os.path.exists(png + ".tmp.png"))

    def test_where_the_snapshots_come_from(self):
        with tempfile.TemporaryDirectory() as folder:
            os.makedirs(os.path.join(folder, "render"))
            for name in ("von_mises_000002.png", "von_mises_000010.png", "velocity_x_1.mp4"):
                open(os.path.join(folder, "render", name), "w").close()
            found, notes = pr.composite_snapshots(folder, {}, [])
            self.assertEqual(found, {"von_mises": os.path.join(folder, "render",
                                                               "von_mises_000010.png")})
            self.assertEqual(len(notes), 2)  # velocity_x, strain_rate: none in render/
            # Given ones (softgrain analyze) are taken as they are, render/ not searched.
            found, notes = pr.composite_snapshots(folder, {}, ["no field snapshot"])
            self.assertEqual((found, notes), ({}, ["no field snapshot"]))

    def test_a_run_without_first_bodies_has_no_composite(self):
        with tempfile.TemporaryDirectory() as folder:
            made_up_run(folder)
            with open(os.path.join(folder, "series.csv"), "w") as f:
                f.write("time,lid_fy\n0,1\n1,2\n")
            summary = pr.read_summary(os.path.join(folder, "analysis"))
            self.assertEqual(pr.plot_composite(folder, os.path.join(folder, "analysis"),
                                               summary, {}, []), (None, None))


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
