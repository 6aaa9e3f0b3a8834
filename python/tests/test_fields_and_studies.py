"""Result.structure / Result.fluid against the files the run writes, and sweep and
converge from Python against the command line (issue 31)."""
import json
import os
import re
import subprocess

import numpy as np
import pytest

import fsicontact

SOURCE = os.environ["FSICONTACT_SOURCE_DIR"]
BINARY = os.environ["FSICONTACT_BINARY"]
CASES = os.path.join(SOURCE, "cases")


def ascii_vtu(path):
    """An ASCII .vtu's arrays by name: Points, connectivity and the data arrays."""
    text = open(path).read()
    arrays = {}
    for m in re.finditer(r'<DataArray[^>]*Name="([^"]+)"[^>]*>([^<]*)</DataArray>', text):
        arrays[m.group(1)] = np.array(m.group(2).split(), dtype=float)
    points = re.search(r"<Points>\s*<DataArray[^>]*>([^<]*)</DataArray>", text)
    arrays["Points"] = np.array(points.group(1).split(), dtype=float).reshape(-1, 3)[:, :2]
    return arrays


def test_the_fields_are_what_the_vtu_files_hold(tmp_path):
    r = fsicontact.run(os.path.join(CASES, "paper-7.2.toml"), out=tmp_path / "run",
                       set={"output.vtu_format": "ascii", "output.png": False})
    s, f = r.structure, r.fluid
    structure = ascii_vtu(tmp_path / "run" / "structure.vtu")  # deformed coordinates (the FSI overlay)
    fluid = ascii_vtu(tmp_path / "run" / "fluid.vtu")
    # ASCII VTU prints 17 significant digits: the same doubles.
    np.testing.assert_array_equal(s.deformed, structure["Points"])
    np.testing.assert_array_equal(s.displacement, structure["displacement"].reshape(-1, 3)[:, :2])
    np.testing.assert_array_equal(s.von_mises, structure["von_mises"])
    np.testing.assert_array_equal(s.contact_status, structure["contact_status"])
    np.testing.assert_array_equal(f.vertices, fluid["Points"])
    np.testing.assert_array_equal(f.pressure, fluid["pressure"])
    np.testing.assert_array_equal(f.velocity, fluid["velocity"].reshape(-1, 3)[:, :2])
    np.testing.assert_array_equal(f.chi, fluid["chi"])
    np.testing.assert_array_equal(f.triangles.ravel(), fluid["connectivity"])
    # And they are the state summary.json describes.
    np.testing.assert_allclose(s.deformed, s.vertices + s.displacement, rtol=0, atol=1e-15)
    assert np.hypot(*s.displacement.T).max() == r.summary["max_displacement"]
    assert s.contact_status.sum() == r.summary["contact"]["active_nodes"]
    assert s.contact_multiplier.max() == r.summary["contact"]["max_multiplier"]
    assert f.triangles.shape == (r.summary["mesh"]["fluid"]["triangles"], 3)
    assert 0 < f.chi.sum() < len(f.chi)


def test_a_p2_structure_has_six_nodes_a_triangle_and_a_contact_run_no_fluid(tmp_path):
    r = fsicontact.run(os.path.join(CASES, "paper-7.1-fig5-coarse.toml"), out=tmp_path / "p2",
                       set={"structure.element": "P2", "output.png": False})
    assert r.fluid is None
    assert r.structure.triangles.shape[1] == 6
    assert r.structure.vertices.shape[0] == r.structure.triangles.max() + 1
    assert np.hypot(*r.structure.displacement.T).max() == r.summary["max_displacement"]


def test_fields_false_keeps_no_arrays(tmp_path):
    r = fsicontact.run(os.path.join(CASES, "paper-7.1-fig5-coarse.toml"), out=tmp_path / "none", fields=False)
    assert r.structure is None and r.fluid is None


def test_a_sweep_from_a_list_of_rows_equals_its_runs(tmp_path):
    rows = [{"coupling.omega": 0.5, "label": "half"}, {"coupling.omega": 0.7, "coupling.scheme": "aitken"}]
    sw = fsicontact.sweep(os.path.join(CASES, "paper-7.2.toml"), rows, out=tmp_path / "sweep")
    assert sw.exit_status == 0 and sorted(sw.runs) == [0, 1]
    assert sw.summary["problem"] == "sweep"
    for i, row in enumerate(rows):
        alone = fsicontact.run(os.path.join(CASES, "paper-7.2.toml"), out=tmp_path / f"alone-{i}",
                               set={k: v for k, v in row.items() if k != "label"})
        assert sw.runs[i].summary["max_displacement"] == alone.summary["max_displacement"]
        np.testing.assert_array_equal(sw.runs[i].structure.displacement, alone.structure.displacement)
    # table.csv: the same runs' values (to the digits it prints).
    np.testing.assert_allclose(sw.table["max_displacement"], [sw.runs[i].summary["max_displacement"] for i in range(2)],
                               rtol=1e-9)


def test_converge_from_a_dict_equals_the_command_line(tmp_path):
    case = os.path.join(CASES, "paper-7.1-fig5-coarse.toml")
    subprocess.run([BINARY, "converge", case, "--out", str(tmp_path / "cli"), "-q"], check=True, capture_output=True)
    cli = json.load(open(tmp_path / "cli" / "summary.json"))
    study = fsicontact.converge(case, out=tmp_path / "py", fields=True)
    assert study.exit_status == 0
    assert study.summary["quantities"] == cli["quantities"]
    assert sorted(study.runs) == ["level-1", "level-2", "level-3"]
    assert study.runs["level-3"].structure.vertices.shape[0] > study.runs["level-1"].structure.vertices.shape[0]


def test_studies_refuse_bad_input_as_the_command_line_does(tmp_path):
    case = os.path.join(CASES, "paper-7.1-fig5-coarse.toml")
    with pytest.raises(fsicontact.InputError, match="--levels 2"):
        fsicontact.converge(case, levels=2, out=tmp_path / "c")
    with pytest.raises(fsicontact.InputError, match="rows"):
        fsicontact.sweep(case, 42, out=tmp_path / "s")
    with pytest.raises(fsicontact.InputError, match="nosuch"):
        fsicontact.sweep(case, [{"fluid.nosuch": 1}], out=tmp_path / "s2")
    assert not os.path.exists(tmp_path / "c") or not os.listdir(tmp_path / "c")
