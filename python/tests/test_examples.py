"""examples/python/ run (quick) and draw their plots (issue 31)."""
import os
import subprocess
import sys

import pytest

EXAMPLES = os.path.join(os.environ["FSICONTACT_SOURCE_DIR"], "examples", "python")


@pytest.mark.parametrize("name", ["table1_study", "obstacle_driver", "time_history", "postprocess"])
def test_the_example_runs_and_draws_its_plot(tmp_path, name):
    done = subprocess.run([sys.executable, os.path.join(EXAMPLES, name + ".py"), "--quick", "--out", str(tmp_path)],
                          capture_output=True, text=True, env=os.environ)
    assert done.returncode == 0, done.stderr
    assert os.path.getsize(tmp_path / (name + ".png")) > 10000
