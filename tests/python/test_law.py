"""hsmu.Law against `hsmu material` on the same history (to 1e-12 relative), and its errors."""
import copy

import numpy as np
import pytest

import hsmu
from conftest import write_column

# Every law of `hsmu material`, with parameters away from the defaults (the test fails if a
# law is added to the program and not here).
LAWS = {
    "boucWen": dict(k0=2.5, alpha=0.04, n=1.6, beta=0.7, gamma=0.3, deltaNu=0.02,
                    deltaEta=0.03, uRef=0.02, fRef=40.0),
    "boucWenPinching": dict(k0=2.0, alpha=0.05, n=1.5, beta=0.6, gamma=0.4, zetaS=0.8, p=1.2,
                            q=0.1, psi=0.05, uRef=0.01, fRef=30.0),
    "mrDamper": dict(c0=2.0, c1=20.0, k0=0.5, k1=0.1, alpha=3.0, A=1.2, beta=0.6, gamma=0.4,
                     n=2.0, uRef=0.01, fRef=2.0),
    "bilinear": dict(k0=1200.0, fy=25.0, b=0.04),
    "elastic": dict(k=350.0),
}


def history(n=3000, amplitude=0.06):
    """A cyclic history with a growing amplitude [the law's deformation unit] over 3 s."""
    t = np.linspace(0.0, 1.0, n)
    return amplitude * t * np.sin(2 * np.pi * 6 * t)


def times(n=3000):
    """The history's times [s] (the rate-dependent MR damper needs them)."""
    return np.linspace(0.0, 3.0, n)


def cli_material(cli, tmp_path, law, params, d):
    hist = tmp_path / f"{law}-history.csv"
    out = tmp_path / f"{law}-out.csv"
    with open(hist, "w") as f:
        f.write("time,deformation\n")
        for t, x in zip(times(len(d)), d):
            f.write(f"{float(t)!r},{float(x)!r}\n")
    args = ["material", "--law", law, "--history", hist, "--out", out]
    for name, value in params.items():
        args += ["--param", f"{name}={value!r}"]
    cli(*args)
    return np.loadtxt(out, delimiter=",", skiprows=1, ndmin=2)


def assert_close(actual, expected):
    scale = np.max(np.abs(expected))
    np.testing.assert_allclose(actual, expected, rtol=1e-12, atol=1e-12 * scale)


def test_every_law_of_the_program_is_covered():
    assert sorted(hsmu.laws()) == sorted(LAWS)


@pytest.mark.parametrize("law", sorted(LAWS))
def test_drive_equals_hsmu_material(cli, tmp_path, law):
    d = history()
    expected = cli_material(cli, tmp_path, law, LAWS[law], d)
    force, tangent = hsmu.Law(law, **LAWS[law]).drive(d, time=times(), tangent=True)
    assert force.dtype == np.float64 and force.shape == d.shape
    np.testing.assert_array_equal(expected[:, 0], d)
    assert_close(force, expected[:, 1])
    assert_close(tangent, expected[:, 2])
    assert np.ptp(force) > 0  # the history did load the law


def test_parameters_are_the_given_ones_and_defaults():
    law = hsmu.Law("bilinear", fy=3.0)
    assert list(law.parameters) == ["k0", "fy", "b"]
    assert law.parameters == {"k0": 1.0, "fy": 3.0, "b": 0.1}
    law.set_parameters(k0=10.0, b=0.2)
    assert law.parameters == {"k0": 10.0, "fy": 3.0, "b": 0.2}
    assert law.initial_tangent == 10.0


def test_bouc_wen_z_is_the_force_split():
    # F = alpha k0 x + (1 - alpha) k0 z (uRef = fRef = 1): z follows from force and deformation.
    p = dict(k0=3.0, alpha=0.1, n=2.0, beta=0.6, gamma=0.4)
    d = history(2000, 2.0)
    force, z = hsmu.Law("boucWen", **p).drive(d, z=True)
    z_from_force = (force - p["alpha"] * p["k0"] * d) / ((1 - p["alpha"]) * p["k0"])
    np.testing.assert_allclose(z, z_from_force, rtol=0, atol=1e-12)
    assert np.max(np.abs(z)) > 0.5  # yielded: z near its bound (A / (beta + gamma))^(1/n) = 1


def test_drive_continues_from_the_committed_state():
    d = history()
    whole = hsmu.Law("boucWen", **LAWS["boucWen"]).drive(d)
    law = hsmu.Law("boucWen", **LAWS["boucWen"])
    first = law.drive(d[:1234])
    assert law.deformation == d[1233] and law.force == first[-1]
    np.testing.assert_array_equal(np.concatenate([first, law.drive(d[1234:])]), whole)


def test_copy_and_reset():
    d = history()
    law = hsmu.Law("boucWenPinching", **LAWS["boucWenPinching"])
    law.drive(d[:1500])
    twin = law.copy()
    deep = copy.deepcopy(law)
    rest = law.drive(d[1500:])
    np.testing.assert_array_equal(twin.drive(d[1500:]), rest)
    np.testing.assert_array_equal(deep.drive(d[1500:]), rest)
    law.reset()
    assert law.deformation == 0.0 and law.force == 0.0
    np.testing.assert_array_equal(law.drive(d), hsmu.Law("boucWenPinching",
                                                         **LAWS["boucWenPinching"]).drive(d))


def test_integer_and_list_input_are_converted():
    law = hsmu.Law("elastic", k=2.0)
    np.testing.assert_array_equal(law.drive([1, 2, 3]), [2.0, 4.0, 6.0])
    law.reset()
    np.testing.assert_array_equal(law.drive(np.arange(3, dtype=np.int32)), [0.0, 2.0, 4.0])


@pytest.mark.parametrize("args", [
    ("material", "--law", "foo"),
    ("material", "--law", "bilinear", "--param", "fyy=1"),
    ("material", "--law", "bilinear", "--param", "b=1.5"),
    ("material", "--law", "boucWen", "--param", "beta=-2", "--param", "gamma=1"),
])
def test_bad_law_or_parameter_gives_the_programs_message(cli, tmp_path, args):
    hist = tmp_path / "h.csv"
    write_column(hist, [0.0, 0.1])
    done = cli(*args, "--history", hist, check=False)
    assert done.returncode == 1
    law = args[2]
    params = {a.split("=")[0]: float(a.split("=")[1]) for a in args[4::2]}
    with pytest.raises(ValueError) as error:
        hsmu.Law(law, **params)
    assert done.stderr.strip() == "hsmu material: " + str(error.value)


@pytest.mark.parametrize("bad, exception, words", [
    (np.zeros((3, 2)), ValueError, "expected a 1-D array, got shape (3, 2)"),
    (np.array(0.5), ValueError, "expected a 1-D array, got shape ()"),
    (np.array([0.1j]), TypeError, "got dtype complex128"),
    (np.array(["a"]), TypeError, "got dtype <U1"),
    (np.array([True]), TypeError, "got dtype bool"),
    (np.array([0.0, np.nan]), ValueError, "value 1 is not finite (nan)"),
    (np.array([np.inf]), ValueError, "value 0 is not finite (inf)"),
    ("abc", TypeError, "got dtype <U3"),
])
def test_bad_deformation_raises_and_loses_nothing(bad, exception, words):
    law = hsmu.Law("bilinear")
    law.drive([0.5])
    with pytest.raises(exception) as error:
        law.drive(bad)
    assert str(error.value).startswith("deformation: ") and words in str(error.value)
    assert law.deformation == 0.5  # the committed state is kept


def test_bad_parameter_values():
    with pytest.raises(TypeError, match="parameter 'k': expected a number, got str"):
        hsmu.Law("elastic", k="1")
    with pytest.raises(TypeError, match="got bool"):
        hsmu.Law("elastic", k=True)
    with pytest.raises(ValueError, match="'k' = nan is not admissible"):
        hsmu.Law("elastic", k=float("nan"))
    law = hsmu.Law("bilinear", fy=2.0)
    with pytest.raises(ValueError, match="unknown parameter 'fyy'"):
        law.set_parameters(fyy=1.0)
    with pytest.raises(ValueError, match="not admissible"):
        law.set_parameters(k0=5.0, b=-1.0)
    assert law.parameters == {"k0": 1.0, "fy": 2.0, "b": 0.1}  # all or nothing


def test_a_rate_dependent_law_needs_times():
    law = hsmu.Law("mrDamper", **LAWS["mrDamper"])
    assert law.rate_dependent and not hsmu.Law("bilinear").rate_dependent
    with pytest.raises(ValueError, match="rate-dependent: give time="):
        law.drive(history())
    with pytest.raises(ValueError, match="time: expected 3000 values"):
        law.drive(history(), time=times()[:10])
    with pytest.raises(ValueError, match="time does not increase at point 1"):
        law.drive([0.0, 0.1], time=[1.0, 1.0])
    # twice as fast, twice the viscous force at small velocities: the times matter
    slow = law.copy().drive(history(), time=times())
    fast = law.copy().drive(history(), time=times() / 2)
    assert np.max(np.abs(fast)) > 1.2 * np.max(np.abs(slow))


def test_z_of_a_law_without_z():
    law = hsmu.Law("bilinear")
    assert law.z is None
    with pytest.raises(ValueError, match="no hysteretic variable z"):
        law.drive([0.1], z=True)


def test_documented():
    for name in ("drive", "reset", "copy", "set_parameters", "parameters"):
        assert getattr(hsmu.Law, name).__doc__, name
    assert "hsmu material" in hsmu.Law.drive.__doc__
