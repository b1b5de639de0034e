# SPDX-License-Identifier: MIT
"""Progress of long bakes on stderr: what, how far, how long so far.

On a terminal a bar redrawn in place; otherwise (make, CI logs) one line at
every tenth of the work. Silent when disabled (tests, the grid search).
"""

import sys
import time


class Progress:
    def __init__(self, total, label, enabled=None):
        self.total = max(int(total), 1)
        self.done = 0
        self.label = label
        self.t0 = time.monotonic()
        self.enabled = sys.stderr.isatty() if enabled is None else bool(enabled)
        self.tty = sys.stderr.isatty()
        self._tenth = 0

    def step(self, n=1):
        self.done += n
        if not self.enabled:
            return
        frac = min(self.done / self.total, 1.0)
        dt = time.monotonic() - self.t0
        if self.tty:
            bar = "#" * int(30 * frac)
            sys.stderr.write("\r%-28s [%-30s] %5.1f%% %6.1fs" % (self.label, bar, 100 * frac, dt))
            if self.done >= self.total:
                sys.stderr.write("\n")
        elif int(10 * frac) > self._tenth or self.done >= self.total:
            self._tenth = int(10 * frac)
            sys.stderr.write("%s: %d/%d (%3.0f%%) %.1f s\n" % (self.label, min(self.done, self.total),
                                                             self.total, 100 * frac, dt))
        sys.stderr.flush()
