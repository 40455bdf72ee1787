"""Progress bars for long runs: the native call runs in a worker thread (it releases the
GIL) while this thread polls the library's current bar and draws it with ``tqdm.auto``
(a widget in a notebook, text in a terminal). Without tqdm installed, or with
``progress=False``, the call runs directly."""

import threading

from . import _native


def _tqdm():
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return None
    return tqdm


def with_progress(call, *args, progress=True, poll=0.1):
    """``call(*args)``, drawing the library's progress bars meanwhile."""
    tqdm = _tqdm() if progress else None
    if tqdm is None:
        return call(*args)
    box = {}

    def work():
        try:
            box["value"] = call(*args)
        except BaseException as e:  # re-raised in the caller's thread
            box["error"] = e

    worker = threading.Thread(target=work, daemon=True)
    worker.start()
    bar, label = None, None
    while worker.is_alive():
        worker.join(poll)
        snap = _native.progress()
        if snap is None:
            continue
        name, position, length = snap
        if bar is None or name != label:
            if bar is not None:
                bar.close()
            bar, label = tqdm(total=length, desc=name, leave=False), name
        bar.total = length
        bar.n = position
        bar.refresh()
    if bar is not None:
        bar.close()
    if "error" in box:
        raise box["error"]
    return box["value"]
