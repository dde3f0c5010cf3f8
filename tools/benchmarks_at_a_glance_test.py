#!/usr/bin/env python3
"""Tests of the at-a-glance table writer (tools/benchmarks_at_a_glance.py), on fixtures, without measuring:
    python3 tools/benchmarks_at_a_glance_test.py
tools/benchmarks_fixture.json is the measurements of one `tools/benchmarks.sh --quick` run."""
import json
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchmarks_at_a_glance as glance  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def stamp(**changes):
    s = {"commit": "abc1234", "date": "2026-12-06 05:00 UTC", "cpu": "AMD EPYC", "cores": 2,
         "mesa": "llvmpipe (LLVM 15.0.6), Mesa 22.3.6", "lp_num_threads": "2", "load_start": 0.4, "load_end": 0.6,
         "quick": False, "runs": 3}
    s.update(changes)
    return s


class TableTest(unittest.TestCase):
    def test_the_stamp_names_commit_date_machine_and_load(self):
        lines = glance.table({"stamp": stamp(), "measured": {}, "read": {}})
        self.assertIn("`abc1234`", lines[0])
        self.assertIn("2026-12-06 05:00 UTC", lines[0])
        self.assertIn("AMD EPYC, 2 cores, llvmpipe (LLVM 15.0.6), Mesa 22.3.6, `LP_NUM_THREADS=2`", lines[0])
        self.assertNotIn("other work shared the machine", lines[0])
        loaded = glance.table({"stamp": stamp(load_start=6.5), "measured": {}, "read": {}})
        self.assertIn("other work shared the machine", loaded[0])

    def test_medians_and_spans_of_the_invocations(self):
        measured = {"cornell": {"shader_paths_per_cpu_second": [1.20e6, 1.30e6, 1.25e6],
                                "native_paths_per_cpu_second": [1e6, 1e6, 1e6], "gpu_over_native": [1.2, 1.3, 1.25]}}
        lines = glance.table({"stamp": stamp(), "measured": measured, "read": {}})
        row = [l for l in lines if l.startswith("| Cornell box, 512x512, nee")][0]
        self.assertIn("1.250 (1.200-1.300) M", row)
        self.assertIn("1.250 (1.200-1.300) times a single-threaded native", row)

    def test_ratios_of_variance_and_cpu_time_give_the_time_to_equal_error(self):
        run = {"tree": {"variance": 1.0, "cpu_seconds": [3.0, 3.0]},
               "power": {"variance": 2.0, "cpu_seconds": [2.0, 2.0]}}
        lines = glance.table({"stamp": stamp(), "measured": {"light_tree": {"runs": [run]}}, "read": {}})
        row = [l for l in lines if l.startswith("| the light tree")][0]
        self.assertIn("the same error in 0.75x the CPU time (0.50x the variance, 1.50x", row)

    def test_a_failed_measurement_is_named_not_dropped(self):
        lines = glance.table({"stamp": stamp(), "measured": {"viewer": {"failed": "RuntimeError: no display\nmore"}},
                              "read": {}})
        self.assertIn("| viewer | not measured in this run: RuntimeError: no display | "
                      "[Viewer](#viewer-frame-time-at-the-default-window-size) |", lines)

    def test_recorded_rows_carry_their_source_commit_and_date(self):
        lines = glance.table({"stamp": stamp(), "measured": {}, "read": {}})
        race = [l for l in lines if l.startswith("| against Blender's Cycles")][0]
        self.assertIn("`e37632f`, 2026-12-06", race)
        report = {"commit": "fff0000", "date": "2026-12-07", "races": [
            {"scene": "cornell", "references": {"cycles": {}},
             "crossings": [{"renderer": "fragpath", "reference": "cycles", "spp": s, "ratio": v}
                           for s, v in ((16, 0.3), (64, 0.4))]}]}
        lines = glance.table({"stamp": stamp(), "measured": {}, "read": {"race": report}})
        race = [l for l in lines if l.startswith("| against Blender's Cycles")][0]
        self.assertIn("cornell 0.30x / 0.40x", race)
        self.assertIn("`fff0000`, 2026-12-07", race)

    def test_every_row_of_a_quick_run_is_written(self):
        with open(os.path.join(HERE, "benchmarks_fixture.json")) as f:
            results = json.load(f)
        lines = glance.table(results)
        rows = [l for l in lines if l.startswith("| ") and not l.startswith("| what")]
        self.assertEqual(len(rows), len(glance.ORDER))
        self.assertFalse([r for r in rows if "not measured" in r])
        self.assertIn("--quick", lines[0])


class RewriteTest(unittest.TestCase):
    def test_only_the_text_between_the_markers_changes(self):
        text = "# B\n\nbefore\n%s\nold table\n%s\n\nafter\n" % (glance.BEGIN, glance.END)
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "B.md")
            with open(path, "w") as f:
                f.write(text)
            glance.rewrite(path, ["new", "table"])
            glance.rewrite(path, ["newer"])
            with open(path) as f:
                self.assertEqual(f.read(), "# B\n\nbefore\n%s\nnewer\n%s\n\nafter\n" % (glance.BEGIN, glance.END))

    def test_a_file_without_markers_is_refused(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "B.md")
            with open(path, "w") as f:
                f.write("no markers\n")
            with self.assertRaises(SystemExit):
                glance.rewrite(path, ["x"])
            with open(path) as f:
                self.assertEqual(f.read(), "no markers\n")

    def test_benchmarks_md_has_the_markers(self):
        with open(os.path.join(HERE, "..", "BENCHMARKS.md")) as f:
            text = f.read()
        self.assertEqual(text.count(glance.BEGIN), 1)
        self.assertEqual(text.count(glance.END), 1)
        self.assertLess(text.index(glance.BEGIN), text.index(glance.END))


if __name__ == "__main__":
    unittest.main()
