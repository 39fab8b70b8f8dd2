"""pandas and xarray views of the results: one tidy row per sample, branch point or grid point. pandas and xarray
are optional: only these views import them, and without them they raise ImportError saying what to install."""
import io

import numpy as np

from ._rbcstab import parameter_table

_PACKAGES = {"pandas": "python3-pandas", "xarray": "python3-xarray"}


def _module(name):
    try:
        return __import__(name)
    except ImportError as e:
        raise ImportError(f"this view needs {name}, which is not installed (Debian: apt install {_PACKAGES[name]}; "
                          f"pip: pip install {name})") from e


def axis_attrs(name):
    """xarray attributes of a parameter axis from the library's parameter table (units '1': dimensionless)."""
    for row in parameter_table():
        if row["name"] == name:
            return {"long_name": row["description"], "symbol": row["unicode"], "units": row["unit"] or "1"}
    return {"long_name": name, "units": "1"}


def frame(columns, attrs=None):
    """A DataFrame of named columns over the same rows; a 2-D column (points x k: eigenvalues, Delta) becomes k
    columns name_0 .. name_{k-1} (or the names a tuple (name, [names]) gives)."""
    pd = _module("pandas")
    flat = {}
    for name, values in columns:
        names = None
        if isinstance(name, tuple):
            name, names = name
        a = np.asarray(values)
        if a.ndim == 1:
            flat[name] = a
        elif a.ndim == 2:
            for k in range(a.shape[1]):
                flat[names[k] if names else f"{name}_{k}"] = a[:, k]
        else:
            raise ValueError(f"column {name!r} has {a.ndim} dimensions: a table takes 1 or 2")
    df = pd.DataFrame(flat)
    df.attrs.update(attrs or {})
    return df


def branch_frame(branch):
    """The CLI's branch CSV as a DataFrame (its rows: the computed points with the located special points in their
    place along the branch; its columns), with ``label`` as integers (<NA> unlabelled), ``type`` as text ('' for a
    regular point) and the special points' ``mode_l``/``mode_m`` (the mode whose eigenvalue crosses at a BP) joined
    by label."""
    pd = _module("pandas")
    df = pd.read_csv(io.StringIO(branch.to_csv()), keep_default_na=False, na_values=[""],
                     float_precision="round_trip")  # the CSV's 17 digits back to the same doubles
    df["label"] = df["label"].astype("Int64")
    df["type"] = df["type"].fillna("").astype(str)
    modes = {sp["label"]: sp for sp in branch.special_points if sp.get("label") is not None}
    for key in ("mode_l", "mode_m"):
        df[key] = pd.array([modes.get(label, {}).get(key) if label is not pd.NA else None for label in df["label"]],
                           dtype="Int64")
    df.attrs.update({"kind": branch.kind, "free_parameter": branch.free_parameter, "status": branch.status})
    return df


def diagram_frame(diagram):
    """One row per grid point: the two axis values, then every per-point array (row-major over (y, x), as the
    CLI's PREFIX.csv)."""
    xs, ys = np.meshgrid(diagram.x, diagram.y)
    columns = [(diagram.axes[0], xs.ravel()), (diagram.axes[1], ys.ravel())]
    columns += [(name, a.ravel()) for name, a in diagram._arrays.items()]
    return frame(columns, {"axes": diagram.axes, "config_hash": diagram.config_hash})


def diagram_dataset(diagram):
    """An xarray Dataset: dimensions (y-axis, x-axis) named after the axes, coordinates their values with the
    parameter table's units and descriptions in attrs, one data variable per per-point array."""
    xr = _module("xarray")
    x_name, y_name = diagram.axes
    coords = {x_name: (x_name, np.array(diagram.x), axis_attrs(x_name)),
              y_name: (y_name, np.array(diagram.y), axis_attrs(y_name))}
    data = {name: ((y_name, x_name), np.array(a)) for name, a in diagram._arrays.items()}
    return xr.Dataset(data, coords=coords,
                      attrs={"classifier": diagram.classifier, "config_hash": diagram.config_hash,
                             "complete": int(diagram.complete)})
