"""One run of the operator on a list of mesh objects: the arrays are read on
the main thread, unwrap() runs on a worker thread (it releases the GIL, so
Blender's interface keeps going), and the results are written back on the
main thread only if every object succeeded. cancel() stops it at the next
progress report; nothing is written then."""
import threading
import time

from . import backend
from .mesh_arrays import MeshArrays


class Job:
    def __init__(self, objects, options, keep_seams=True, protect="sharp_edge", uv_map_name=None, program="",
                 one_atlas=False):
        self.unwrap, self.backend = backend.unwrap_function(program)  # raises RuntimeError if there is none
        # one atlas: every object's charts packed together at one texel density (unwrap_scene())
        self.unwrap_scene = backend.unwrap_scene_function() if one_atlas else None
        self.objects = list(objects)
        self.options = dict(options)
        self.uv_map_name = uv_map_name
        self.arrays = [MeshArrays(o.data, keep_seams=keep_seams, protect=protect) for o in self.objects]
        self.results = [None] * len(self.objects)
        self.error = None          # the exception that stopped the run
        self.cancelled = False
        self.current = 0           # index of the object being unwrapped
        self.phase = ""
        self.seconds = 0.0
        self._cancel = threading.Event()
        self._thread = None

    # -- worker side
    def _progress(self, phase, **info):
        self.phase = phase
        return not self._cancel.is_set()

    def run(self):
        """Unwraps every object (blocking)."""
        start = time.perf_counter()
        try:
            if self.unwrap_scene is not None:
                self.results = self.unwrap_scene([(a.V, a.F) for a in self.arrays],
                                                 seams=[a.seams for a in self.arrays],
                                                 forbidden=[a.forbidden for a in self.arrays],
                                                 progress=self._progress, **self.options)
                self.current = len(self.arrays) - 1
            for i, a in enumerate(self.arrays if self.unwrap_scene is None else []):
                self.current = i
                self.results[i] = self.unwrap(a.V, a.F, seams=a.seams, forbidden=a.forbidden,
                                              progress=self._progress, **self.options)
        except Exception as e:  # reported on the main thread
            cancelled = getattr(e, "name", "") == "ERROR_CANCELED"
            self.cancelled = cancelled
            self.error = None if cancelled else e
        self.seconds = time.perf_counter() - start

    def start(self):
        self._thread = threading.Thread(target=self.run, name="uv_unwrap_seams", daemon=True)
        self._thread.start()

    def running(self):
        return self._thread is not None and self._thread.is_alive()

    def cancel(self):
        self._cancel.set()

    def status(self):
        name = self.objects[self.current].name if self.objects else ""
        return "Unwrapping %s (%d/%d): %s  (Esc: cancel)" % (name, self.current + 1, len(self.objects), self.phase)

    # -- main thread
    def succeeded(self):
        return not self.cancelled and self.error is None and all(r is not None for r in self.results)

    def apply(self):
        """Writes every result (call on the main thread, in object mode)."""
        for o, a, r in zip(self.objects, self.arrays, self.results):
            a.write(o.data, r, self.uv_map_name)

    def warnings(self):
        return ["%s: %s" % (o.name, w) for o, r in zip(self.objects, self.results) if r is not None
                for w in r.warnings]

    def summary(self):
        parts = ["%s: %d charts, E_d %.3f, E_s %.2f%s" % (o.name, r.stats["charts"], r.stats["distortion"],
                                                         r.stats["seam_length"],
                                                         ", page %d" % r.page if getattr(r, "page", -1) >= 0 else "")
                 for o, r in zip(self.objects, self.results)]
        return "; ".join(parts) + " (%.1f s)" % self.seconds
