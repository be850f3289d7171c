"""llfsmc --promela: what the exporter refuses (naming machine, state, section, line and why), the
ringlet order it emits, and that every shipped machine and the schedule export. spin itself runs in
the SpinVerify.* tests."""

import io
import os
import tempfile
import unittest

from support import ROOT, SCHEMA, cli

HEAD = """machine M
external laser : LaserSummary read
external motion : MotionCommand write
assume laser.nearest_range in {0.3, 1.0}
"""


def export(text, extra=()):
    """(status, stderr lines, promela text)."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "m.machine")
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        out = os.path.join(tmp, "m.pml")
        err = io.StringIO()
        status = cli.run([path, "--schema", SCHEMA, "--promela", out, *extra], err)
        pml = open(out, encoding="utf-8").read() if os.path.isfile(out) else ""
        return status, [line.replace(path, "m.machine") for line in err.getvalue().splitlines()], pml


class Refusals(unittest.TestCase):
    def test_an_untranslatable_action_names_machine_state_section_line_and_why(self):
        status, err, _ = export(HEAD + """state A initial
  OnEntry {
    motion.stop = std::isnan(laser.nearest_range);
  }
end
ltl p: [] motion.stop
""")
        self.assertEqual(status, 1)
        self.assertEqual(len(err), 1, err)
        self.assertIn("m.machine:7:1: error: machine M, state A, OnEntry: cannot translate", err[0])
        self.assertIn("it calls 'std::isnan'", err[0])

    def test_an_input_without_a_domain_is_refused_at_its_declaration(self):
        status, err, _ = export("""machine M
external laser : LaserSummary read
state A initial
  -> A when laser.valid_beams > 3
end
""")
        self.assertEqual(status, 1)
        self.assertTrue(err[0].startswith("m.machine:2:10: error: machine M reads input LaserSummary.valid_beams"), err)

    def test_a_value_that_is_not_a_thousandth_is_refused(self):
        status, err, _ = export(HEAD.replace("1.0}", "1.0005}") + "state A initial\nend\n")
        self.assertEqual(status, 1)
        self.assertIn("not a multiple of 0.001", err[0])

    def test_a_statement_writing_nothing_observed_is_dropped_not_refused(self):
        status, err, pml = export(HEAD + """state A initial
  Internal {
    motion.velocity = std::isnan(laser.nearest_range) ? 0.0 : 1.0;
    motion.stop = laser.nearest_range < 0.5;
  }
end
ltl p: [] motion.stop
""")
        self.assertEqual((status, err), (0, []))
        self.assertIn("M_x_motion_stop = (M_x_laser_nearest_range < 500)", pml)
        self.assertNotIn("velocity", pml)

    def test_a_loop_is_one_statement_dropped_when_it_names_nothing_modelled(self):
        status, err, pml = export(HEAD + """local n : int = 0
state A initial
  Internal {
    for (int i = 0; i < 3; ++i) { if (i == 1) continue; n += i; }
    motion.stop = laser.nearest_range < 0.5;
  }
end
ltl p: [] motion.stop
""")
        self.assertEqual((status, err), (0, []))
        self.assertIn("M_x_motion_stop = (M_x_laser_nearest_range < 500)", pml)

    def test_an_if_writing_only_declared_sets_is_either_branch(self):
        status, err, pml = export(HEAD + """local seen : bool = false
assume seen in {false, true}
state A initial
  Internal {
    if (ringlet::behaviour::obstacle_ahead(laser.nearest_range)) { seen = true; }
    motion.stop = seen;
  }
end
ltl p: [] motion.stop
""")
        self.assertEqual((status, err), (0, []))
        self.assertIn("if :: true -> if :: M_l_seen = 0 :: M_l_seen = 1 fi :: true -> skip fi", pml)


class RingletOrder(unittest.TestCase):
    def test_guards_in_declared_order_then_internal_then_write_back(self):
        status, err, pml = export(HEAD + """state A initial
  OnEntry {
    motion.stop = true;
  }
  OnExit {
    motion.stop = false;
  }
  Internal {
    motion.stop = true;
  }
  -> B when laser.nearest_range < 0.5
  -> A when after_ms(30)
end
state B
end
ltl p: [] motion.stop
""")
        self.assertEqual((status, err), (0, []))
        body = pml[pml.index(":: M_st == 0 ->"):pml.index(":: M_st == 1 ->")]
        order = [body.index(s) for s in ("M_x_laser_nearest_range = wb_LaserSummary_nearest_range",
                                         "if :: M_ent -> M_ent = false; M_t = 0; M_x_motion_stop = true",
                                         "if :: (M_x_laser_nearest_range < 500) -> M_x_motion_stop = false; M_st = 1",
                                         "(M_t >= 3) -> M_x_motion_stop = false; M_st = 0",
                                         "else -> M_x_motion_stop = true",
                                         "wb_MotionCommand_stop = M_x_motion_stop")]
        self.assertEqual(order, sorted(order), body)

    def test_requests_keep_the_highest_priority(self):
        status, err, pml = export(HEAD + "state A initial\nend\n")
        self.assertEqual(status, 0, err)
        self.assertLess(pml.index("M_req == 3"), pml.index("M_req == 2"))
        self.assertLess(pml.index("M_req == 2"), pml.index("M_req == 1"))


class Shipped(unittest.TestCase):
    def test_every_shipped_machine_and_the_schedule_export(self):
        d = os.path.join(ROOT, "behaviour", "machines")
        for f in sorted(os.listdir(d)):
            if f.endswith((".machine", ".schedule")):
                with self.subTest(f), tempfile.TemporaryDirectory() as tmp:
                    err = io.StringIO()
                    status = cli.run([os.path.join(d, f), "--schema", SCHEMA, "--promela",
                                      os.path.join(tmp, "m.pml")], err)
                    self.assertEqual(status, 0, err.getvalue())
                    with open(os.path.join(tmp, "m.pml"), encoding="utf-8") as f:
                        self.assertIn("ltl ", f.read())


if __name__ == "__main__":
    unittest.main()
