"""deferred_workbench.tradeoff(search=True) (issue 34, tradeoff --search), run
by ctest as test_tradeoff.py is: every evaluation is a row (point = its
number, with its step and proposal), the evaluations stay under max_evals,
the result fits the budget and names its row; bad arguments raise with the
CLI's messages before anything renders."""
import os
import tempfile
import unittest

import deferred_workbench as dw

KEYWORDS = dict(scene="default", size=(48, 27), metric="rms", frames=6, warmup=1, resamples=200, quiet=True)


class SearchTest(unittest.TestCase):
    def test_rows_bound_and_result(self):
        with tempfile.TemporaryDirectory() as tmp:
            csv = os.path.join(tmp, "search.csv")
            r = dw.tradeoff(search=True, budget_ms=100000, max_evals=6, csv=csv, **KEYWORDS)
            self.assertTrue(os.path.exists(csv))
        s = r["search"]
        self.assertNotIn("pick", r)
        rows = r["rows"]
        self.assertEqual(len(rows), s["evaluations"])
        self.assertLessEqual(s["evaluations"], 6)
        self.assertEqual([row["point"] for row in rows], list(range(len(rows))))
        self.assertEqual(rows[0]["proposal"], "start")
        self.assertEqual(rows[0]["step"], "1")
        self.assertTrue(s["fits"])
        best = rows[s["evaluation"]]
        self.assertLess(best["time_ms_hi"], 100000)
        self.assertIn(best["pick"], ("pick", "tied", "fits"))
        for knob, value in s["found"].items():
            self.assertEqual(best[knob], value, knob)
        self.assertTrue(any(line.startswith("search: found") for line in s["lines"]))
        self.assertEqual(sum(step["evaluations"] for step in s["steps"]), s["evaluations"])
        self.assertGreater(s["grid_points"], s["evaluations"])
        self.assertEqual(r["grid"]["search"]["max_evals"], 6)

    def test_bad_arguments(self):
        for kwargs, says in [(dict(search=True), "--search needs a budget"),
                             (dict(search=True, budget_ms=5, max_evals=0), "max_evals"),
                             (dict(budget_ms=5, knobs="speed/quality", max_evals=4), "max_evals bounds search=True"),
                             (dict(search=True, budget_ms=5, sweep={"ssao.samples": [4, 8]}),
                              "--search walks the speed/quality knobs itself")]:
            with self.assertRaises(ValueError) as e:
                dw.tradeoff(**dict(KEYWORDS, **kwargs))
            self.assertIn(says, str(e.exception), kwargs)


if __name__ == "__main__":
    unittest.main()
