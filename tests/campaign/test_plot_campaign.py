#!/usr/bin/python3
"""scripts/plot_campaign.py on made-up campaign tables: the label table, the panels left out
(empty or constant pairs and map quantities) and what correlations.png then holds, the alpha~
slices and their titles, the error bars of mu.

    /usr/bin/python3 tests/campaign/test_plot_campaign.py SCRIPTS_DIR   (ctest runs it)

Exit status 77 (ctest: skipped) without numpy, matplotlib and scipy.
"""
import csv
import math
import os
import struct
import sys
import tempfile
import unittest

sys.path.insert(0, sys.argv.pop(1) if len(sys.argv) > 1 else "scripts")
try:
    import numpy as np
    import scipy  # noqa: F401 (the correlations need it)
    import plot_campaign as pc
except ImportError as e:
    print(f"skipped: {e}")
    sys.exit(77)


def png_size(path):
    """(width, height) from the PNG's IHDR chunk."""
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR", path
    return struct.unpack(">II", head[16:24])


def run(status="done", **values):
    row = {"id": "r", "status": status}
    row.update({k: ("" if v is None else repr(v)) for k, v in values.items()})
    return row


class Labels(unittest.TestCase):
    def test_the_papers_quantities_have_their_symbols(self):
        keys = {k for pair in pc.DEFAULT_PAIRS for k in pair} | set(pc.MAP_QUANTITIES)
        keys |= {"stiffness_tilde", "cohesion_tilde", "viscosity_tilde", "mu_error", "mu_std"}
        for key in keys:
            self.assertNotEqual(pc.label_of(key), key, key)
        self.assertEqual(pc.label_of("mu"), r"$\mu$")
        self.assertEqual(pc.label_of("bulk_share"), r"$p_{wb}$")
        self.assertEqual(pc.label_of("stiffness_tilde"), r"$\tilde{E}$")

    def test_a_requested_coordinate_says_so_and_other_keys_stay(self):
        self.assertEqual(pc.label_of("viscosity_tilde_requested"),
                         r"$\tilde{\alpha}$ (requested)")
        self.assertEqual(pc.label_of("materials.0.young"), "materials.0.young")


class Panels(unittest.TestCase):
    rows = [run(x=1.0, y=2.0, flat=0.0, some=1.0, gone=None),
            run(x=2.0, y=1.0, flat=0.0, some=2.0, gone=None),
            run(x=3.0, y=5.0, flat=0.0, some=None, gone=None),
            run(x=4.0, y=3.0, flat=0.0, some=None, gone=None),
            run(status="failed", x=9.0, y=9.0, flat=7.0, some=3.0, gone=1.0)]

    def test_only_pairs_with_coefficients_get_a_panel(self):
        table = pc.correlation_table(self.rows, [("x", "y"), ("x", "flat"), ("x", "some"),
                                                 ("x", "gone")])
        why = {(t[0], t[1]): t[5] for t in table}
        self.assertIsNone(why[("x", "y")])
        self.assertEqual(why[("x", "flat")], "flat is 0 for every run")  # failed run ignored
        self.assertEqual(why[("x", "some")], "2 runs with both (3 needed)")
        self.assertEqual(why[("x", "gone")], "no run has both")
        for xk, yk, n, r, rho, reason in table:  # a panel exactly when r and rho exist
            self.assertEqual(reason is None, not math.isnan(r) and not math.isnan(rho))

    def test_correlations_png_holds_the_drawn_panels_and_the_csv_every_pair(self):
        header = ["id", "status", "x", "y", "flat", "some", "gone"]
        with tempfile.TemporaryDirectory() as folder:
            pc.plot_correlations(self.rows, header, folder, "test",
                                 [("x", "y"), ("x", "flat"), ("x", "some"), ("y", "x")])
            self.assertEqual(png_size(os.path.join(folder, "correlations.png")), (880, 380))
            with open(os.path.join(folder, "correlations.csv")) as f:
                lines = list(csv.DictReader(f))
            self.assertEqual([(l["x"], l["y"]) for l in lines],
                             [("x", "y"), ("x", "flat"), ("x", "some"), ("y", "x")])
            self.assertEqual([l["pearson"] == "" for l in lines], [False, True, True, False])

    def test_a_constant_or_empty_map_quantity_gets_no_panel(self):
        e, c = np.array([1.0, 2.0, 1.0, 2.0]), np.array([0.0, 0.0, 1.0, 1.0])
        self.assertIsNone(pc.why_no_map(e, c, np.array([0.1, 0.2, 0.3, 0.5])))
        self.assertEqual(pc.why_no_map(e, c, np.zeros(4)), "0 for every run")
        self.assertEqual(pc.why_no_map(e, c, np.full(4, np.nan)), "no run of the slice has it")
        self.assertEqual(pc.why_no_map(e, c, np.array([0.1, 0.2, np.nan, np.nan])),
                         "2 runs of the slice have it (3 needed)")


class Slices(unittest.TestCase):
    def test_runs_sliced_by_the_requested_alpha_titled_by_the_realized_range(self):
        rows = [run(viscosity_tilde_requested=-2.5, viscosity_tilde=-2.31),
                run(viscosity_tilde_requested=-2.5, viscosity_tilde=-2.29),
                run(viscosity_tilde_requested=-1.5, viscosity_tilde=-1.2)]
        header = ["id", "viscosity_tilde_requested", "status", "viscosity_tilde"]
        slices = pc.alpha_slices(rows, header, 0.5)
        self.assertEqual([(a, list(pick)) for a, pick, _ in slices],
                         [(-2.5, [True, True, False]), (-1.5, [False, False, True])])
        a = pc.column(rows, "viscosity_tilde")
        alpha, pick, how = slices[0]
        self.assertEqual(pc.slice_title(alpha, a[pick], how, 0.5),
                         r", $\tilde{\alpha} \in$"
                         " [\u22122.31, \u22122.29] (requested \u22122.5)")

    def test_without_a_request_the_realized_alpha_is_rounded(self):
        rows = [run(viscosity_tilde=-2.31), run(viscosity_tilde=-1.4)]
        slices = pc.alpha_slices(rows, ["id", "status", "viscosity_tilde"], 0.5)
        self.assertEqual([a for a, _, how in slices], [-2.5, -1.5])
        self.assertEqual({how for _, _, how in slices}, {"rounded"})


class ErrorBars(unittest.TestCase):
    def test_the_error_of_the_mean_else_the_std_and_which(self):
        bars, what = pc.mu_error_bars([run(mu_error=0.01, mu_std=0.1),
                                       run(mu_error=0.02, mu_std=0.2)])
        self.assertEqual(list(bars), [0.01, 0.02])
        self.assertIn("error of the mean", what)
        bars, what = pc.mu_error_bars([run(mu_std=0.1), run(mu_std=0.2)])
        self.assertEqual(list(bars), [0.1, 0.2])
        self.assertIn("standard deviation", what)
        bars, what = pc.mu_error_bars([run(mu_error=0.01, mu_std=0.1), run(mu_std=0.2)])
        self.assertEqual(list(bars), [0.01, 0.2])
        self.assertIn("for 1 runs without it", what)


class Fits(unittest.TestCase):
    def test_the_plane_fit_recovers_a_plane(self):
        c = np.array([-1.0, 0.0, 1.0, -1.0, 0.0, 1.0])
        e = np.array([1.0, 1.0, 1.0, 2.0, 2.0, 2.0])
        a, b, d, r2 = pc.fit_plane(c, e, 30.0 + 20.0 * c - 5.0 * e)
        for got, want in ((a, 30.0), (b, 20.0), (d, -5.0), (r2, 1.0)):
            self.assertAlmostEqual(got, want, places=9)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
