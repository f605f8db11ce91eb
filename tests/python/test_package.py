"""The installed package: found where cmake --install put it, its library found without
LD_LIBRARY_PATH, the run definition's defaults the C library's own, unknown fields refused."""

import math
import os

import pytest

import crawlsim


def test_imports_from_the_install_prefix_and_loads_its_library():
    prefix = os.path.realpath(os.environ["CRAWLSIM_TEST_PREFIX"])
    assert os.path.realpath(crawlsim.__file__).startswith(prefix + os.sep)
    assert "LD_LIBRARY_PATH" not in os.environ
    lib = os.path.realpath(crawlsim.library_path())
    assert lib.startswith(prefix + os.sep), lib
    assert crawlsim.version()


def test_rundef_starts_at_the_c_defaults():
    d = crawlsim.RunDef()
    f = d.fields()
    # cs_defaultRunDef: strings NULL, numbers NaN ("the scene's or the driver's"), except these
    assert f["scene"] in (None, "flat-road")
    assert f["pressure_scale"] == 1.0
    assert f["t_end"] == 0.0
    assert f["friction"] is None and f["dt"] is None and f["gait"] is None
    assert f["actuator_set"] == [] and f["no_gait"] == 0


def test_rundef_keywords_and_attributes_set_fields():
    d = crawlsim.RunDef(friction=0.5, legs="strain", actuator_set={"S1": 45})
    d.t_end = 2
    assert d.friction == 0.5 and d.legs == "strain" and d.t_end == 2.0
    assert d.actuator_set == ["S1=45"]
    d.friction = None
    assert d.friction is None


def test_rundef_unknown_field_names_the_nearest():
    with pytest.raises(crawlsim.Error, match="did you mean friction"):
        crawlsim.RunDef(frictoin=0.5)
    d = crawlsim.RunDef()
    with pytest.raises(crawlsim.Error, match="did you mean t_end"):
        d.tend = 3


@pytest.mark.parametrize("field,value", [("friction", "a lot"), ("scene", 3), ("no_gait", 0.5),
                                         ("actuator_set", "S1=40"), ("gait", "a\0b")])
def test_rundef_wrong_type_is_refused_with_the_field(field, value):
    with pytest.raises(crawlsim.Error, match=field):
        crawlsim.RunDef(**{field: value})


def test_rundef_nan_means_default():
    assert crawlsim.RunDef(friction=math.nan).friction is None
