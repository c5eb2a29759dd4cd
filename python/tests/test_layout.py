"""The ctypes mirrors in pflip._types agree with pf.h as the C compiler sees it.

A C program generated from the ctypes definitions prints sizeof and offsetof of every struct and
field and the value of every enumerator; a struct that grew in pf.h (a field appended) changes its
sizeof, a retyped field its size, and an enumerator, struct or entry point pf.h gained but
Python lacks is found by scanning the header. Needs a C compiler ($CC, else cc) and
PFLIP_INCLUDE_DIRS.
"""
import ctypes
import os
import pathlib
import re
import shutil
import subprocess

import pytest

from pflip import _types as t


def include_dirs():
    env = os.environ.get("PFLIP_INCLUDE_DIRS")
    if env:
        return [d for d in env.split(os.pathsep) if d]
    root = pathlib.Path(__file__).resolve().parents[2]
    return [str(root / "include"), str(root / "build" / "include")]


def header_text():
    for d in include_dirs():
        p = pathlib.Path(d) / "pf" / "pf.h"
        if p.exists():
            return p.read_text()
    pytest.fail(f"pf/pf.h not found in {include_dirs()}")


def members(enum):
    """name -> member of every enumerator, aliases included (iterating an IntFlag skips multi-bit
    members such as Feature.ALL)."""
    return dict(enum.__members__)


def c_program():
    lines = ["#include <pf/pf.h>", "#include <stdio.h>", "#include <stddef.h>", "int main(void) {"]
    for cls, c_name in t.C_NAMES.items():
        lines.append(f'  printf("size {c_name} %zu\\n", sizeof({c_name}));')
        for field, *_ in cls._fields_:
            lines.append(f'  printf("field {c_name}.{field} %zu %zu\\n", offsetof({c_name}, {field}), '
                         f"sizeof((({c_name}*)0)->{field}));")
    for enum, prefix in t.C_ENUMS.items():
        for name in members(enum):
            lines.append(f'  printf("value {prefix}{name} %lld\\n", (long long)({prefix}{name}));')
    for name in t.C_CONSTANTS:
        lines.append(f'  printf("value {name} %lld\\n", (long long)({name}));')
    lines += ['  printf("size enum %zu\\n", sizeof(pf_result));', "  return 0;", "}"]
    return "\n".join(lines) + "\n"


@pytest.fixture(scope="module")
def c_layout(tmp_path_factory):
    cc = os.environ.get("CC") or shutil.which("cc") or shutil.which("gcc")
    assert cc, "no C compiler: set CC"
    d = tmp_path_factory.mktemp("layout")
    src, exe = d / "layout.c", d / "layout"
    src.write_text(c_program())
    cmd = [cc, "-std=c99", str(src), "-o", str(exe)] + [f"-I{i}" for i in include_dirs()]
    build = subprocess.run(cmd, capture_output=True, text=True)
    assert build.returncode == 0, f"a field or enumerator named in pflip._types is not in pf.h:\n{build.stderr}"
    out = subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout
    layout = {}
    for line in out.splitlines():
        kind, name, *numbers = line.split()
        layout[(kind, name)] = tuple(int(n) for n in numbers)
    return layout


@pytest.mark.parametrize("cls", list(t.C_NAMES), ids=lambda c: t.C_NAMES[c])
def test_struct_matches_c(c_layout, cls):
    c_name = t.C_NAMES[cls]
    for field, ctype in cls._fields_:
        offset, size = c_layout[("field", f"{c_name}.{field}")]
        assert (getattr(cls, field).offset, ctypes.sizeof(ctype)) == (offset, size), f"{c_name}.{field}"
    assert ctypes.sizeof(cls) == c_layout[("size", c_name)][0], (
        f"sizeof({c_name}) differs: a field was added to pf.h and not to pflip/_types.py")


def test_enum_values_match_c(c_layout):
    assert ctypes.sizeof(t.c_enum) == c_layout[("size", "enum")][0]
    for enum, prefix in t.C_ENUMS.items():
        for name, member in members(enum).items():
            assert c_layout[("value", prefix + name)][0] == member.value, prefix + name
    for name, value in t.C_CONSTANTS.items():
        assert c_layout[("value", name)][0] == value, name


def test_every_enumerator_of_the_header_is_mirrored():
    # Enumerators are lines "PF_NAME = value" in pf.h; COUNT and FORCE32 are sizes, not values.
    names = set(re.findall(r"^\s*(PF_[A-Z0-9_]+)\s*=", header_text(), re.M))
    assert len(names) > 50, "the enumerator pattern no longer matches pf.h"
    mirrored = {prefix + name for enum, prefix in t.C_ENUMS.items() for name in members(enum)} | set(t.C_CONSTANTS)
    missing = sorted(n for n in names - mirrored if not n.endswith(("_FORCE32", "_COUNT")))
    assert not missing, f"pf.h enumerators missing from pflip/_types.py: {missing}"


def test_every_numeric_define_of_the_header_is_mirrored():
    # Capacities such as PF_MAX_FORCE_FIELDS are "#define PF_NAME number" lines.
    defines = set(re.findall(r"^#define\s+(PF_[A-Z0-9_]+)\s+\d+\s*$", header_text(), re.M))
    assert {"PF_MAX_FORCE_FIELDS", "PF_MAX_OBSTACLES"} <= defines, "the define pattern no longer matches pf.h"
    missing = sorted(defines - set(t.C_CONSTANTS))
    assert not missing, f"pf.h constants missing from pflip/_types.py C_CONSTANTS: {missing}"


def test_every_struct_of_the_header_is_mirrored():
    structs = set(re.findall(r"^typedef struct (pf_[a-z0-9_]+) \{", header_text(), re.M))
    assert structs, "the struct pattern no longer matches pf.h"
    assert structs == set(t.C_NAMES.values())


def test_every_entry_point_of_the_header_has_a_prototype():
    # A pf_* function pf.h declares (PF_API) that pflip._lib does not declare would be called with
    # ctypes' default int arguments and return; and a prototype of a name pf.h lacks is stale.
    from pflip import _lib

    functions = set(re.findall(r"^PF_API\s[^;]*?\b(pf_[a-z0-9_]+)\s*\(", header_text(), re.M))
    assert {"pf_create", "pf_step", "pf_get_domain_motion"} <= functions, "the PF_API pattern no longer matches pf.h"
    assert sorted(functions - set(_lib._PROTOTYPES)) == [], "pf.h entry points without a prototype in pflip/_lib.py"
    assert sorted(set(_lib._PROTOTYPES) - functions) == [], "prototypes in pflip/_lib.py of no pf.h entry point"


def check_appended(c_layout, cls, c_name, after, appended):
    """The fields appended follow field after in cls as in C, each 4 bytes at the next offset, so
    the offsets an older caller knows stay."""
    names = [name for name, _ in cls._fields_]
    i = names.index(after)
    assert names[i:i + len(appended) + 1] == [after] + appended, c_name
    offset, size = c_layout[("field", f"{c_name}.{after}")]
    for name in appended:
        assert c_layout[("field", f"{c_name}.{name}")] == (offset + size, 4), f"{c_name}.{name}"
        offset, size = offset + size, 4
    assert c_layout[("size", c_name)][0] == ctypes.sizeof(cls) >= offset + size, c_name


def test_whitewater_layout(c_layout):
    # pf_whitewater and pf_whitewater_buffers as pf.h declares them, and the fields whitewater
    # appended to pf_stats and pf_ssf_params, after the ones an older caller knows (whose
    # offsets stay), so a caller's struct_size tells the library which of them it has.
    assert c_layout[("size", "pf_whitewater")][0] == ctypes.sizeof(t.Whitewater) == 60
    assert c_layout[("size", "pf_whitewater_buffers")][0] == ctypes.sizeof(t.WhitewaterBuffers) == 20
    check_appended(c_layout, t.Stats, "pf_stats", "gpu_particle_bytes", ["whitewater_count", "render_whitewater_gpu_ms"])
    check_appended(c_layout, t.SsfParams, "pf_ssf_params", "filter_world_radius",
                   ["whitewater_radius", "whitewater_opacity", "skip_whitewater", "spray_radius_scale"])
    assert {m.name: m.value for m in t.WhitewaterKind} == {"SPRAY": 0, "FOAM": 1, "BUBBLE": 2}
    assert c_layout[("value", "PF_FEATURE_WHITEWATER")][0] == t.Feature.WHITEWATER == 1 << 6
    assert c_layout[("value", "PF_FLAG_WHITEWATER_FULL")][0] == t.Flag.WHITEWATER_FULL == 1 << 7


def test_viscosity_layout(c_layout):
    # pf_viscosity as pf.h declares it (coupling_rounds appended to its first 20 bytes), and the
    # solve's two figures appended to pf_stats after whitewater's.
    assert c_layout[("size", "pf_viscosity")][0] == ctypes.sizeof(t.Viscosity) == 24
    check_appended(c_layout, t.Viscosity, "pf_viscosity", "free_slip", ["coupling_rounds"])
    check_appended(c_layout, t.Stats, "pf_stats", "render_whitewater_gpu_ms",
                   ["viscosity_iterations", "viscosity_residual"])
    assert c_layout[("value", "PF_FEATURE_VISCOSITY")][0] == t.Feature.VISCOSITY == 1 << 7
    assert c_layout[("value", "PF_FEATURE_ALL")][0] == t.Feature.ALL


def test_surface_tension_layout(c_layout):
    # pf_surface_tension as pf.h declares it: struct_size, then the tension. It adds nothing to
    # pf_stats (the substeps it costs show in pf_stats.substeps; the strain after the viscosity's
    # figures is the step clock's).
    assert c_layout[("size", "pf_surface_tension")][0] == ctypes.sizeof(t.SurfaceTension) == 8
    assert c_layout[("field", "pf_surface_tension.tension")] == (4, 4)
    names = [name for name, _ in t.Stats._fields_]
    assert names[-1] == "strain"
    assert c_layout[("value", "PF_FEATURE_SURFACE_TENSION")][0] == t.Feature.SURFACE_TENSION == 1 << 8
    assert c_layout[("value", "PF_FEATURE_ALL")][0] == t.Feature.ALL


def test_strain_layout(c_layout):
    # pf_stats.strain appended last, after the viscosity's two figures.
    check_appended(c_layout, t.Stats, "pf_stats", "viscosity_residual", ["strain"])
