"""tippe for Python: a ctypes binding of libtippe (docs/python.md).

    import tippe
    d = tippe.load("/usr/share/tippe/designs/m12-setscrew.json", set=["parts.screw.height_mm=12"])
    print(d.sweep())                 # the zone table; .zones, .report (tippe sweep --json)
    d.eval(10)["A_over_C"]           # tippe eval --json at Z2 = 10 mm, as a dict
    run = d.check(15)                # one central launch; run.t_s, run.theta_rad (NumPy)
    batch = d.launch(15, n=50)       # hand launches; batch.counts, batch.verdict, ...

Why ctypes: libtippe is a plain C library whose entry points take and return
plain values and JSON text, so a binding needs no compiler and no build step, works
with every Python 3 that Debian ships (a compiled extension would pin one), and
its numbers are the command's: each report is printed by the library with the
command's own builders (tippe_sweep_text_*), so they agree to the last digit.

The library is found as TIPPE_LIBRARY names it, else beside an install made by
cmake --install or the .deb, else as libtippe.so.0 on the loader's path.
"""
import ctypes
import ctypes.util
import json
import math
import os

import numpy as np

__all__ = ["TippeError", "Design", "Sweep", "Zone", "Launch", "Batch", "load", "eval",
           "sweep", "check", "launch", "library_path", "shipped_designs"]

TIPPE_OK, TIPPE_ECOMPUTE, TIPPE_EINPUT = 0, 1, 2


class TippeError(Exception):
    """An error of libtippe: its message (naming the file, the field and what is
    wrong), code (2: bad input, 1: a computation failed) and field (a JSON path
    or a parameter's name, "" when none)."""

    def __init__(self, message, code=TIPPE_EINPUT, field=""):
        super().__init__(message)
        self.code = code
        self.field = field


class _Error(ctypes.Structure):
    # tippe_error (include/tippe/base.h)
    _fields_ = [("code", ctypes.c_int), ("msg", ctypes.c_char * 1024),
                ("field", ctypes.c_char * 128)]


def _candidates():
    env = os.environ.get("TIPPE_LIBRARY")
    if env:
        yield env
        return
    try:  # written by cmake --install: where libtippe is, relative to this file
        from . import _install
        yield os.path.normpath(os.path.join(os.path.dirname(__file__), _install.LIBRARY))
    except ImportError:
        pass
    yield "libtippe.so.0"
    found = ctypes.util.find_library("tippe")
    if found:
        yield found


def _open():
    errors = []
    for c in _candidates():
        try:
            return ctypes.CDLL(c), c
        except OSError as e:
            errors.append(str(e))
    raise ImportError("tippe: cannot load libtippe (install tippe, or set TIPPE_LIBRARY to "
                      "build/libtippe.so.0): " + "; ".join(errors))


_lib, _lib_path = _open()


def library_path():
    """The libtippe that was loaded."""
    return _lib_path


_p = ctypes.c_void_p
_lib.tippe_design_load.argtypes = [ctypes.c_char_p, ctypes.POINTER(ctypes.c_char_p), ctypes.c_int,
                                   ctypes.POINTER(_p), ctypes.POINTER(_Error)]
_lib.tippe_design_load_text.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_size_t,
                                        ctypes.c_char_p, ctypes.POINTER(ctypes.c_char_p),
                                        ctypes.c_int, ctypes.POINTER(_p), ctypes.POINTER(_Error)]
_lib.tippe_design_free.argtypes = [_p]
_lib.tippe_design_free.restype = None
_lib.tippe_design_warning.argtypes = [_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_size_t]
_lib.tippe_design_note.argtypes = [_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_size_t]
_lib.tippe_file_shipped_dir.argtypes = [ctypes.c_char_p, ctypes.c_size_t]
_text = ctypes.POINTER(ctypes.c_char)
_lib.tippe_sweep_text_eval.argtypes = [_p, ctypes.c_double, ctypes.POINTER(_text),
                                       ctypes.POINTER(_Error)]
_lib.tippe_sweep_text_sweep.argtypes = [_p, ctypes.c_double, ctypes.c_double,
                                        ctypes.POINTER(_text), ctypes.POINTER(_Error)]
_lib.tippe_sweep_text_check.argtypes = [_p, ctypes.c_double, ctypes.c_double,
                                        ctypes.POINTER(_text), ctypes.POINTER(_Error)]
_lib.tippe_sweep_text_launch.argtypes = [_p, ctypes.c_double, ctypes.c_long, ctypes.c_uint64,
                                         ctypes.POINTER(_text), ctypes.POINTER(_Error)]
_lib.tippe_sweep_text_free.argtypes = [_text]
_lib.tippe_sweep_text_free.restype = None


def _raise(err):
    raise TippeError(err.msg.decode("utf-8", "replace"), err.code,
                     err.field.decode("utf-8", "replace"))


def shipped_designs():
    """The folder of the shipped designs and materials table (installed, or the
    checkout's designs/ for a build tree's library); None if there is none."""
    buf = ctypes.create_string_buffer(4096)
    return buf.value.decode() if _lib.tippe_file_shipped_dir(buf, len(buf)) else None


def _call_text(fn, *args):
    out = _text()
    err = _Error()
    if fn(*args, ctypes.byref(out), ctypes.byref(err)) != TIPPE_OK:
        _raise(err)
    try:
        return json.loads(ctypes.string_at(out).decode("utf-8"))
    finally:
        _lib.tippe_sweep_text_free(out)


def _arrays(d):
    """Lists of numbers as float arrays (null: NaN)."""
    return {k: np.array([np.nan if x is None else x for x in v], dtype=float)
            for k, v in d.items()}


class Zone:
    """A zone of a sweep: group ("I", "IIa", ...), its ends and widths in mm and the
    tolerance bands at its ends (None where it ends with the travel)."""
    __slots__ = ("group", "z2_from_mm", "z2_to_mm", "width_mm", "robust_width_mm",
                 "band_from_mm", "band_to_mm", "within_travel", "ends_on")

    def __init__(self, z):
        for k in self.__slots__:
            setattr(self, k, z.get(k))

    def __repr__(self):
        return "Zone(%s, %.3f .. %.3f mm, width %.3f mm, robust %.3f mm)" % (
            self.group, self.z2_from_mm, self.z2_to_mm, self.width_mm,
            self.robust_width_mm if self.robust_width_mm is not None else math.nan)


class Sweep:
    """A design's zones along the travel of its weight (tippe sweep --json as
    .report), with .zones (Zone objects) and .three_in_one."""

    def __init__(self, report):
        self.report = report
        self.zones = [Zone(z) for z in report["zones"]]
        self.three_in_one = report["three_in_one"]

    def __str__(self):
        rows = ["%-5s %10s %10s %10s %10s" % ("zone", "from_mm", "to_mm", "width_mm",
                                             "robust_mm")]
        for z in self.zones:
            rows.append("%-5s %10.3f %10.3f %10.3f %10.3f" % (
                z.group, z.z2_from_mm, z.z2_to_mm, z.width_mm,
                z.robust_width_mm if z.robust_width_mm is not None else math.nan))
        n = self.report.get("robust_narrowest_zone_mm")
        rows.append("3-in-1: %s%s" % ("yes" if self.three_in_one else "no",
                                      "; narrowest robust zone %.3f mm" % n if n else ""))
        return "%s (%s)\n%s" % (self.report["design"], self.report["file"], "\n".join(rows))

    __repr__ = __str__


class Launch:
    """One central hand launch (tippe check --json as .report) with its trajectory
    as NumPy arrays: t_s, theta_rad, theta_dot_rad_s, phi_dot_rad_s, spin_rad_s,
    Rn_N, E_J, D_J, J_kg_m3_s; .verdict."""

    def __init__(self, report):
        self.trajectory = _arrays(report.pop("trajectory"))
        self.report = report
        self.verdict = report["verdict"]
        for k, v in self.trajectory.items():
            setattr(self, k, v)

    def __repr__(self):
        return "Launch(%s at Z2 = %g mm: %s, %d samples to %.3g s)" % (
            self.report["design"], self.report["z2_mm"], self.verdict, len(self.t_s),
            self.t_s[-1] if len(self.t_s) else 0)


class Batch:
    """Hand launches drawn as tippe launch draws them: .counts by verdict and one
    entry per launch as arrays (.verdict, .spin_rad_s, .theta0_rad, .t_s,
    .theta_final_rad, .spin_final_rad_s, .t_flip_s)."""

    def __init__(self, report):
        self.counts = report["counts"]
        launches = dict(report["launches"])
        self.verdict = np.array(launches.pop("verdict"))
        for k, v in _arrays(launches).items():
            setattr(self, k, v)

    def __repr__(self):
        return "Batch(%d launches: %s)" % (len(self.verdict), ", ".join(
            "%s %d" % (k, v) for k, v in self.counts.items() if v))


class Design:
    """A loaded design (a file or a dict) with its overrides; read-only. Its
    warnings and notes (a likely unit mistake, the shipped materials table read
    in place of a missing one) are in .warnings and .notes."""

    def __init__(self, source, set=()):
        sets = [str(s) for s in (set or ())]
        arr = (ctypes.c_char_p * max(len(sets), 1))(*[s.encode() for s in sets])
        handle = _p()
        err = _Error()
        if isinstance(source, dict):
            text = json.dumps(source).encode()
            shipped = shipped_designs()
            rc = _lib.tippe_design_load_text(b"the design", text, len(text),
                                             (shipped or "").encode(), arr, len(sets),
                                             ctypes.byref(handle), ctypes.byref(err))
        else:
            rc = _lib.tippe_design_load(os.fsencode(source), arr, len(sets),
                                        ctypes.byref(handle), ctypes.byref(err))
        if rc != TIPPE_OK:
            _raise(err)
        self._h = handle
        self.source = source
        self.set = sets
        self.warnings = self._texts(_lib.tippe_design_warning)
        self.notes = self._texts(_lib.tippe_design_note)

    def _texts(self, fn):
        out, buf = [], ctypes.create_string_buffer(1024)
        while fn(self._h, len(out), buf, len(buf)):
            out.append(buf.value.decode("utf-8", "replace"))
        return out

    def __del__(self):
        h = getattr(self, "_h", None)
        if h:
            _lib.tippe_design_free(h)
            self._h = None

    def eval(self, z2_mm):
        """tippe eval --json at Z2 (mm), as a dict (SI units)."""
        return _call_text(_lib.tippe_sweep_text_eval, self._h, float(z2_mm))

    def sweep(self, from_mm=None, to_mm=None):
        """The zones along [from_mm, to_mm] (default: the stated travel), with bands."""
        f, t = (0.0, 0.0) if from_mm is None or to_mm is None else (from_mm, to_mm)
        return Sweep(_call_text(_lib.tippe_sweep_text_sweep, self._h, float(f), float(t)))

    def check(self, z2_mm, spin_rad_s=2 * math.pi * 15):
        """One central hand launch at Z2 (mm) and spin (rad/s; tippe check's default
        15 rev/s) under the command's default options, with its trajectory."""
        return Launch(_call_text(_lib.tippe_sweep_text_check, self._h, float(z2_mm),
                                 float(spin_rad_s)))

    def launch(self, z2_mm, n=50, seed=1):
        """n hand launches at Z2 (mm) drawn with seed, as tippe launch -n N --seed S."""
        return Batch(_call_text(_lib.tippe_sweep_text_launch, self._h, float(z2_mm), int(n),
                                int(seed)))

    def __repr__(self):
        return "Design(%r%s)" % (self.source if not isinstance(self.source, dict) else "<dict>",
                                 ", set=%r" % self.set if self.set else "")


def load(source, set=()):
    """A design from a file path or a dict, with --set-style overrides
    ("parts.rod.material=nylon")."""
    return source if isinstance(source, Design) and not set else Design(source, set)


def eval(design, z2_mm, set=()):
    """tippe eval --json of a design (path, dict or Design) at Z2 (mm)."""
    return load(design, set).eval(z2_mm)


def sweep(design, set=(), from_mm=None, to_mm=None):
    """The sweep of a design (path, dict or Design): print() it for the zone table."""
    return load(design, set).sweep(from_mm, to_mm)


def check(design, z2_mm, spin_rad_s=2 * math.pi * 15, set=()):
    """One central launch of a design with its trajectory (Launch)."""
    return load(design, set).check(z2_mm, spin_rad_s)


def launch(design, z2_mm, n=50, seed=1, set=()):
    """A batch of hand launches of a design (Batch)."""
    return load(design, set).launch(z2_mm, n, seed)
