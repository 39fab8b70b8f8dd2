"""Progress of long calls: a callable ``bar(done, total, eta)`` that rbcstab's long calls update, counting the
call's own unit of work (diagram points, branch points); ``total`` is 0 when the end is not known in advance (a
continuation ends where its branch does) and ``eta`` then 0.

``progress_bar(True)`` gives a tqdm bar (Debian's python3-tqdm) when tqdm can be imported, else a plain-text
line on stderr at most once a second; ``progress_bar(False)`` (or None) gives None; any other callable is used
as it is; a tqdm bar of the user's is updated (and left open). A bar is a context manager: leaving it closes it (tqdm draws its last state, the text bar prints the
final line once).
"""
import sys
import time

__all__ = ["progress_bar", "TextProgress"]


def _duration(seconds):
    """'42.0 s', '3 min 05 s' or '2 h 07 min': the remaining time as a person reads it."""
    if seconds >= 3600:
        return f"{int(seconds // 3600)} h {int(seconds // 60) % 60:02d} min"
    if seconds >= 60:
        return f"{int(seconds // 60)} min {int(seconds) % 60:02d} s"
    return f"{seconds:.1f} s"


class _Bar:
    """A bar as a context manager: leaving the block closes it."""

    def close(self):
        pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False


class TextProgress(_Bar):
    """Plain-text progress on a stream (default stderr): one line per `interval` seconds and a final line."""

    def __init__(self, description="rbcstab", unit="points", interval=1.0, stream=None):
        self.description = description
        self.unit = unit
        self.interval = interval
        self.stream = stream
        self._last = None  # monotonic time of the last line
        self._state = None  # (done, total, eta) last seen
        self._printed = None  # the state of the last line printed

    def __call__(self, done, total, eta):
        self._state = (done, total, eta)
        now = time.monotonic()
        if self._last is None:
            self._last = now  # the first line waits one interval: a quick call prints only its final line
        elif now - self._last >= self.interval:
            self._last = now
            self._print()

    def _print(self):
        done, total, eta = self._state
        if not total:  # a count without a known end (continuation points)
            line = f"{self.description}: {done} {self.unit}"
        else:
            line = f"{self.description}: {done}/{total} {self.unit} ({100.0 * done / total:.0f}%)"
            if done < total:
                line += f", ETA {_duration(eta)}" if eta and eta > 0 else ", ETA ?"
        stream = self.stream if self.stream is not None else sys.stderr
        stream.write(line + "\n")
        stream.flush()
        self._printed = self._state

    def close(self):
        if self._state is not None and self._printed != self._state:
            self._print()


class _TqdmProgress(_Bar):
    """A tqdm bar driven by (done, total, eta); tqdm estimates the rate itself."""

    def __init__(self, tqdm, description, unit):
        self._tqdm = tqdm
        self._description = description
        self._unit = unit
        self._bar = None

    def __call__(self, done, total, eta):
        if self._bar is None:
            self._bar = self._tqdm(total=total or None, desc=self._description, unit=self._unit, initial=done)
        elif done > self._bar.n:
            self._bar.update(done - self._bar.n)

    def close(self):
        if self._bar is not None:
            self._bar.close()


class _TqdmInstance(_Bar):
    """The user's own tqdm bar: its count (and total, when known) follow the call; the user closes it."""

    def __init__(self, bar):
        self._bar = bar

    def __call__(self, done, total, eta):
        if total and self._bar.total != total:
            self._bar.total = total
            self._bar.refresh()
        if done > self._bar.n:
            self._bar.update(done - self._bar.n)


class _Passive(_Bar):
    """A user's callable: used as it is, nothing to close."""

    def __init__(self, function):
        self._function = function

    def __call__(self, done, total, eta):
        self._function(done, total, eta)


def _tqdm():
    try:
        from tqdm.auto import tqdm  # a widget in Jupyter, text in a terminal
    except ImportError:
        return None
    return tqdm


def progress_bar(progress, description="rbcstab", unit="points", use_tqdm=None):
    """The bar for a ``progress=`` argument: True -> tqdm if importable (use_tqdm=False: never) else TextProgress
    on stderr; False or None -> None; a callable f(done, total, eta) -> f. Anything else is a TypeError."""
    if progress is None or progress is False:
        return None
    if progress is True:
        tqdm = _tqdm() if use_tqdm is not False else None
        if tqdm is not None:
            return _TqdmProgress(tqdm, description, unit)
        return TextProgress(description, unit)
    if callable(progress):
        return _Passive(progress)
    if all(hasattr(progress, a) for a in ("update", "n", "total", "refresh")):  # a tqdm bar (or one like it)
        return _TqdmInstance(progress)
    raise TypeError(f"progress must be True, False, None, a callable f(done, total, eta) or a tqdm bar, got "
                    f"{type(progress).__name__}")
