"""softgrain.Scenario: file, dict and TOML text give the same model; errors carry their place."""

import copy

import pytest

import softgrain
from conftest import EXAMPLES


def fingerprint(scenario):
    info = scenario.info(timing=False)
    return info["model_hash"], info["settings_hash"]


def test_dict_and_toml_round_trips_build_the_same_model():
    s = softgrain.Scenario.from_file(EXAMPLES / "shear-cell-small.toml")
    d = s.to_dict()
    assert d["shear_cell"]["grains"] == 60 and d["materials"][0]["name"] == "soft"
    again = softgrain.Scenario.from_dict(d)
    assert again.to_dict() == d
    assert fingerprint(again) == fingerprint(s)
    assert fingerprint(softgrain.Scenario.from_toml(s.to_toml())) == fingerprint(s)
    # The fingerprint does see a change (the test could fail).
    changed = copy.deepcopy(d)
    changed["materials"][0]["young"] = 11.0
    assert fingerprint(softgrain.Scenario.from_dict(changed)) != fingerprint(s)


def test_to_toml_gives_the_text_read():
    path = EXAMPLES / "shear-cell-small.toml"
    s = softgrain.Scenario.from_file(path)
    assert s.to_toml() == path.read_text()  # the file as written, comments kept
    text = softgrain.Scenario.from_dict(s.to_dict()).to_toml()
    assert "node_spacing = 0.15\n" in text and "[[materials]]" in text  # shortest exact floats


@pytest.mark.parametrize("example", ["shear-cell-small", "shear-cell-deformable",
                                     "shear-cell-explicit", "compaction-box", "mixed-box",
                                     "free-grains", "shear-cell-si",
                                     "shear-cell-deformable-pressure"])
def test_every_example_survives_the_dict_round_trip(example):
    s = softgrain.Scenario.from_file(EXAMPLES / f"{example}.toml")
    again = softgrain.Scenario.from_dict(s.to_dict(), base_dir=EXAMPLES)
    assert again.to_dict() == s.to_dict()
    assert again.name == s.name and again.duration == s.duration


def test_info_is_what_softgrain_info_prints():
    info = softgrain.Scenario.from_file(EXAMPLES / "shear-cell-small.toml").info()
    assert info["bodies"] == 62  # 60 grains and two first bodies
    assert info["field_nodes"] > 0 and info["gauss_points"] > info["field_nodes"]
    assert 0 < info["stable_step"] < 0.01
    assert 0.5 < info["contact_share"] < 1.0  # the penalty sets most of this cell's step (95%)
    assert info["integrator"] == "explicit"
    # Both integrators timed as `softgrain info` does, the configured one marked; the explicit
    # one's step is the model's own estimate, and the IMEX step is not damping-limited.
    explicit, imex = info["integrators"]
    assert (explicit["integrator"], imex["integrator"]) == ("explicit", "imex")
    assert explicit["configured"] and not imex["configured"]
    assert explicit["stable_step"] == pytest.approx(info["stable_step"], rel=1e-12)
    assert imex["step_limit"] == "wave-speed-limited"
    # The IMEX integrator with the scenario's imex settings: the default split solve keeps one
    # single-precision factor per grain (4 bytes per entry of its envelope, a part of the lower
    # triangle), the exact solve a double-precision operator and factor (2 x 8 bytes per entry
    # of the full matrix): 8 times the bytes if the envelope were the whole triangle, 16 if it
    # were half of it.
    assert "factors_mib" not in explicit
    text = softgrain.Scenario.from_file(EXAMPLES / "shear-cell-small.toml").to_toml()
    exact = softgrain.Scenario.from_toml(
        text.replace("[time]", '[time]\nimex_objective = "exact"', 1),
        base_dir=EXAMPLES).info()["integrators"][1]
    assert 8.0 < exact["factors_mib"] / imex["factors_mib"] < 16.0
    for cost in (explicit, imex):
        assert cost["seconds_per_step"] > 0
        assert cost["seconds_per_time_unit"] == pytest.approx(
            cost["seconds_per_step"] / cost["stable_step"], rel=1e-12)
    assert "integrators" not in softgrain.Scenario.from_file(
        EXAMPLES / "shear-cell-small.toml").info(timing=False)


def test_a_bad_key_names_the_key_and_its_line(small_cell):
    d = copy.deepcopy(small_cell)
    assert d["materials"][0]["name"] == "soft"
    d["materials"][0]["poisson"] = 0.5  # must be in (-1, 0.5)
    with pytest.raises(softgrain.ScenarioError) as raised:
        softgrain.Scenario.from_dict(d)
    error = raised.value
    assert error.key == "materials[0].poisson"
    assert error.file == "<dict>"
    assert "0.5" in error.detail and isinstance(error, softgrain.Error)
    # The line is that of the key in the TOML text from_dict read, which is to_toml()'s text
    # of the same dict (here with a valid value: the same lines).
    d["materials"][0]["poisson"] = 0.25
    lines = softgrain.Scenario.from_dict(d).to_toml().splitlines()
    assert lines[error.line - 1] == "poisson = 0.25"


def test_an_unknown_key_in_a_file(tmp_path):
    text = (EXAMPLES / "shear-cell-small.toml").read_text()
    text = text.replace("[time]\nduration = 15.0", "[time]\nduration = 15.0\ndurration = 2")
    path = tmp_path / "typo.toml"
    path.write_text(text)
    with pytest.raises(softgrain.ScenarioError) as raised:
        softgrain.Scenario.from_file(path)
    lines = text.splitlines()
    assert raised.value.file == str(path)
    assert raised.value.key.endswith("durration")
    assert lines[raised.value.line - 1].startswith("durration")


def test_a_syntax_error_has_line_and_column(tmp_path):
    path = tmp_path / "broken.toml"
    path.write_text('name = "x"\n[time\nduration = 1\n')
    with pytest.raises(softgrain.ScenarioError) as raised:
        softgrain.Scenario.from_file(path)
    assert raised.value.line == 2 and raised.value.column is not None
    assert raised.value.key is None


def test_a_missing_file_is_an_error(tmp_path):
    with pytest.raises(softgrain.Error, match="does not exist"):
        softgrain.Scenario.from_file(tmp_path / "none.toml")


def test_values_that_toml_cannot_hold_are_refused(small_cell):
    d = copy.deepcopy(small_cell)
    d["time"]["duration"] = object()
    with pytest.raises(TypeError, match="time.duration"):
        softgrain.Scenario.from_dict(d)
