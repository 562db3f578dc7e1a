"""The Python module `usvid` (docs/python.md) as a notebook user calls it: numpy arrays out,
dicts for models and metrics, ValueError with the command line's message for bad arguments."""
import os
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import usvid  # first: it finds numpy where Debian's python3-numpy put it (docs/python.md)

import numpy as np  # noqa: E402

SOURCE = os.environ.get("USVID_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


class ModuleTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.train = usvid.simulate(vessel="odin3dof", maneuver="random-steps", noise=0.005, seed=3)

    def test_simulate_returns_numpy_arrays_of_every_channel(self):
        self.assertIn("t", self.train)
        for name in ("t", "u", "v", "r", "tau_x", "tau_y", "tau_n"):
            self.assertIsInstance(self.train[name], np.ndarray, name)
            self.assertEqual(self.train[name].shape, self.train["t"].shape, name)
        self.assertTrue(np.all(np.diff(self.train["t"]) > 0))
        # Seeded: the same call gives the same numbers.
        again = usvid.simulate(vessel="odin3dof", maneuver="random-steps", noise=0.005, seed=3)
        np.testing.assert_array_equal(again["u"], self.train["u"])

    def test_recorded_inputs_and_effects(self):
        inputs = {k: self.train[k] for k in ("t", "tau_x", "tau_y", "tau_n")}
        clean = usvid.simulate(vessel="odin3dof", inputs=inputs)
        slow = usvid.simulate(vessel="odin3dof", inputs=inputs, effects={"damping": 2.0})
        # Twice the damping: a lower top speed on the same forces.
        self.assertLess(np.max(slow["u"]), np.max(clean["u"]))

    def test_sindy_predicts_a_held_out_multisine(self):
        model = usvid.identify(self.train, method="sindy", vessel="odin3dof", threads=2, seed=5)
        self.assertEqual(model["method"], "sindy")
        self.assertEqual(set(model["equations"]), {"u", "v", "r"})
        test = usvid.simulate(vessel="odin3dof", maneuver="multisine", noise=0.005, seed=4)
        metrics = usvid.evaluate(model, test)
        for state in ("u", "v", "r"):
            self.assertGreaterEqual(metrics[state]["fit_percent"], 90.0, state)

    def test_sindy_takes_its_threshold_library_and_derivative(self):
        # The options SINDy declares (docs/options.md), by the names the suites use: a fixed
        # threshold instead of cross-validation, a library without products, and
        # Savitzky-Golay derivatives; model.json echoes what it ran with.
        model = usvid.identify(self.train, method="sindy", vessel="odin3dof", threshold=0.05,
                               library=["constant", "abs"], derivative="sg:21:3")
        self.assertEqual(model["options"]["threshold"], 0.05)
        self.assertEqual(model["options"]["library"], ["constant", "abs"])
        self.assertEqual(model["preprocessing"]["derivative"], "sg:21:3")
        for state, details in model["sindy"].items():
            if state == "features":
                continue
            self.assertEqual(details["threshold"], 0.05, state)
            for term in details["library"]:
                # products of two variables ("u*v") are not offered; abs(x)*x is
                self.assertFalse("*" in term and not term.startswith("abs("), term)

    def test_the_example_methods_two_options_reach_python(self):
        # lti (docs/adding-a-method.md) declares ridge and constant and nothing else.
        msd = usvid.simulate(vessel="msd", maneuver="random-steps", seed=1)
        model = usvid.identify(msd, method="lti", vessel="msd", ridge=0.5, constant="no")
        self.assertEqual(model["options"], {"ridge": 0.5, "constant": "no"})
        self.assertNotIn("v.1", model["parameters"])
        with self.assertRaises(ValueError) as raised:
            usvid.identify(msd, method="lti", vessel="msd", constant="maybe")
        self.assertIn("method lti: option 'constant' \"maybe\" is not allowed: one of yes, no",
                      str(raised.exception))

    def test_diagnose_finds_nothing_wrong_with_the_vessel_itself(self):
        d = usvid.diagnose(self.train, vessel="odin3dof", discover=False)
        self.assertEqual(d["cause"], "none")
        self.assertEqual(d["model"]["vessel"], "odin3dof")

    def test_the_gil_is_released_while_usvid_works(self):
        # A Python thread keeps running while another identifies: a call that held the GIL
        # would stop it for the whole fit.
        done = threading.Event()
        worker = threading.Thread(target=lambda: (usvid.identify(
            self.train, method="fossen-ceres", vessel="odin3dof", threads=1), done.set()))
        start = last = time.monotonic()
        worker.start()
        longest_pause = 0.0
        while not done.is_set():
            now = time.monotonic()
            longest_pause, last = max(longest_pause, now - last), now
        worker.join()
        fit_seconds = time.monotonic() - start
        self.assertLess(longest_pause, 0.5 * fit_seconds, (longest_pause, fit_seconds))

    def test_several_records_are_fitted_jointly(self):
        # A list of records is one joint fit, nothing run across the joins (docs/data.md).
        runs = [usvid.simulate(vessel="msd", maneuver="random-steps", seed=s, duration=150)
                for s in (1, 2)]
        model = usvid.identify(runs, method="lti", vessel="msd")
        self.assertEqual(model["train"]["samples"], sum(len(r["t"]) for r in runs))
        self.assertTrue(any("2 stretches" in n for n in model["preprocessing"]["notes"]))

    def test_bad_arguments_raise_value_error_and_write_nothing(self):
        before = set(os.listdir(tempfile.gettempdir()))
        cases = [
            (lambda: usvid.simulate(vessel="titanic", maneuver="zigzag"), "titanic"),
            (lambda: usvid.simulate(vessel="odin3dof", maneuver="loop"), "loop"),
            (lambda: usvid.simulate(vessel="odin3dof"), "exactly one of"),
            (lambda: usvid.identify(self.train, method="magic", vessel="odin3dof"), "magic"),
            (lambda: usvid.identify(self.train, method="gp", vessel="odin3dof", colour=1),
             "unknown option 'colour'"),
            # An option of another method, out of range, or of the wrong type: one line naming
            # the method, the key and what is allowed, before any fit.
            (lambda: usvid.identify(self.train, method="gp", vessel="odin3dof", causes=3),
             "method gp: unknown option 'causes' (its options: preset"),
            (lambda: usvid.identify(self.train, method="sindy", vessel="odin3dof", population=50),
             "method sindy: unknown option 'population' (its options: threshold"),
            (lambda: usvid.identify(self.train, method="gp", vessel="odin3dof", max_depth=40),
             "method gp: option 'max_depth' 40 is not allowed: a whole number in [2, 17]"),
            (lambda: usvid.identify(self.train, method="sindy", vessel="odin3dof",
                                    threshold="small"),
             "method sindy: option 'threshold' \"small\" is not allowed: a finite number >= 0"),
            (lambda: usvid.identify(self.train, method="sindy", vessel="odin3dof",
                                    library=["cubic"]),
             "option 'library' [\"cubic\"] is not allowed: a list of constant, products, abs"),
            (lambda: usvid.identify(self.train, method="gp", vessel="odin3dof", threads=-1),
             "threads must be a whole number"),
            (lambda: usvid.identify([], method="sindy", vessel="odin3dof"),
             "an empty list of records"),
            (lambda: usvid.identify({"u": np.zeros(3)}, method="sindy", vessel="odin3dof"),
             "no time channel 't'"),
            (lambda: usvid.identify({"t": np.array([0.0, 2.0, 1.0])}, method="sindy",
                                    vessel="odin3dof"), "strictly increasing"),
            (lambda: usvid.evaluate({"equations": {"u": "u +"}}, self.train), "equation for u"),
            (lambda: usvid.compare({"vessels": ["odin3dof"]}), "missing field"),
        ]
        for call, message in cases:
            with self.assertRaises(ValueError) as raised:
                call()
            self.assertIn(message, str(raised.exception))
            self.assertNotIn("\n", str(raised.exception).strip())
        self.assertEqual(set(os.listdir(tempfile.gettempdir())) - before, set())

    def test_the_notebook_example_runs(self):
        env = dict(os.environ)
        result = subprocess.run([sys.executable, os.path.join(SOURCE, "docs", "examples",
                                                              "notebook.py")],
                                capture_output=True, text=True, env=env, timeout=600)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("least-squares: ok", result.stdout)


if __name__ == "__main__":
    unittest.main()
