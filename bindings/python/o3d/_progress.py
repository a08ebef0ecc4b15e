"""Progress display for long calls: tqdm when installed, else a one-line bar on stderr."""
import contextlib
import sys


class ProgressBar:
    def __init__(self, desc, file=None):
        self._file = file if file is not None else sys.stderr
        self._desc = desc
        self._last = -1
        self._tqdm = None
        try:
            from tqdm import tqdm  # optional
        except ImportError:
            tqdm = None
        if tqdm is not None:
            self._tqdm = tqdm(total=100, desc=desc, file=self._file, unit="%", leave=True)

    def update(self, fraction):
        percent = int(max(0.0, min(1.0, float(fraction))) * 100)
        if percent <= self._last:
            return
        if self._tqdm is not None:
            self._tqdm.update(percent - max(self._last, 0))
        else:
            filled = percent // 5
            self._file.write(f"\r{self._desc} [{'#' * filled}{'.' * (20 - filled)}] {percent:3d}%")
            self._file.flush()
        self._last = percent

    def close(self):
        if self._tqdm is not None:
            self._tqdm.close()
        elif self._last >= 0:
            self._file.write("\n")
            self._file.flush()


@contextlib.contextmanager
def progress_context(desc, print_progress, callback):
    """The C progress callable for (print_progress, callback), or None when neither is asked for."""
    if callback is not None and not callable(callback):
        raise TypeError("callback: expected a callable")
    bar = ProgressBar(desc) if print_progress else None
    if bar is None and callback is None:
        yield None
        return

    def progress(fraction):
        if bar is not None:
            bar.update(fraction)
        return bool(callback(fraction)) if callback is not None else False

    try:
        yield progress
    finally:
        if bar is not None:
            bar.close()
