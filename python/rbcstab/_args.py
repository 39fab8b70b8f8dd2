"""Argument checks shared by the package's functions: a wrong type is a TypeError naming the argument, its type
and value (values are the library's to range-check: ValueError with the allowed range)."""
import numbers
import os

import numpy as np

from ._rbcstab import Scene


def scene(value):
    if not isinstance(value, Scene):
        raise TypeError(f"scene must be a rbcstab.Scene, got {type(value).__name__}")
    return value


def number(name, value):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be a number, got {type(value).__name__} {value!r}")
    return float(value)


def integer(name, value):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be an integer, got {type(value).__name__} {value!r}")
    return int(value)


def flag(name, value):
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be True or False, got {type(value).__name__} {value!r}")
    return bool(value)


def text(name, value, default=None):
    """A string; None gives `default` when one is given."""
    if value is None and default is not None:
        return default
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, got {type(value).__name__} {value!r}")
    return value


def sequence(name, value, what):
    """A list from a sequence (not a string, whose characters would pass for names); None -> [] (the default).
    Its length is the library's to check, so that the message says what the field takes."""
    if value is None:
        return []
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or not hasattr(value, "__iter__"):
        raise TypeError(f"{name} must be a sequence of {what}, got {type(value).__name__} {value!r}")
    return list(value)


def names(name, value):
    return [text(name, v) for v in sequence(name, value, "names")]


def numbers_(name, value):
    return [number(name, v) for v in sequence(name, value, "numbers")]


def integers(name, value):
    return [integer(name, v) for v in sequence(name, value, "integers")]


def path(name, value):
    """A file name (str or path-like); None -> '' (none)."""
    if value is None:
        return ""
    if not isinstance(value, (str, os.PathLike)):
        raise TypeError(f"{name} must be a path, got {type(value).__name__} {value!r}")
    p = os.fspath(value)
    if not p:
        raise ValueError(f"{name} = '' is empty: must be a file name")
    return p


class Columns:
    """Named numpy columns in self._columns: table["name"], table.columns; self._what names the table."""
    _what = "this table"

    @property
    def columns(self):
        """The names of the columns, in order (``table[name]`` is each as a numpy array)."""
        return list(self._columns)

    def __getitem__(self, name):
        try:
            return self._columns[name]
        except KeyError:
            raise KeyError(f"{name!r} is not a column of {self._what}: must be one of {', '.join(self._columns)}") \
                from None


def times(name, value, ndim=None):
    """A float array of times from a number or an array-like (TypeError otherwise, naming the argument); with
    ndim, of that many dimensions (ValueError). Their values are the library's to range-check."""
    if isinstance(value, (str, bytes, bool, np.bool_)):
        raise TypeError(f"{name} must be a number or an array of numbers, got {type(value).__name__} {value!r}")
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a number or an array of numbers, got {type(value).__name__} {value!r}") from None
    if ndim is not None and a.ndim != ndim:
        raise ValueError(f"{name} must be a {ndim}-D array of times, got shape {a.shape}")
    return a
