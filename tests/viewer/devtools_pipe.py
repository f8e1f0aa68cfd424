"""One headless Chromium for a whole test session, driven over the DevTools
protocol through a pipe.

A browser process per page cost about 0.7 s a page (a measured layout
1.8 s: loaded twice, to find the strip of its window the page does not
get); a tab of a running browser costs 0.2 to 0.6 s, most of it the
page's own virtual-time budget played.  So a test worker starts ONE
browser (``--remote-debugging-pipe``: the browser reads JSON commands,
each ended by a NUL byte, on its file descriptor 3 and writes replies and
events the same way on 4) and opens each page in a new tab of it.  A page
is loaded as ``--dump-dom --virtual-time-budget`` loads it: virtual time
paused while the page is fetched, then ``budget_ms`` of it granted, the
DOM read when the browser says the budget is spent.  No wall-clock wait
enters: how far the page has played is its virtual clock's, whatever the
machine's load (to within a frame or two of the page's animation, which
a loaded machine may start a little later, as with ``--dump-dom``).
"""

import fcntl
import json
import os
import select
import shutil
import signal
import subprocess
import tempfile
import time

#: The flags of a quiet headless browser: no first-run work, no network
#: fetches of its own (they would hold virtual time), no GPU.
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-extensions", "--mute-audio")

#: The longest a command or a page may take [s] before the test fails
#: (a hung browser must not hang the suite); far above any page's need.
TIMEOUT_S = 120.0

#: The expression ``--dump-dom`` evaluates: the doctype, then the markup.
DOM = ("(document.doctype ? new XMLSerializer().serializeToString(document.doctype) + '\\n' : '')"
       " + document.documentElement.outerHTML")


def _onto_3_and_4(commands, replies):
    """What the child runs before it becomes the browser: the pipe's ends
    onto the descriptors the browser reads and writes (moved above 10
    first, as either may be 3 or 4 already).  ``dup2`` makes them
    inheritable; every other descriptor Python opened is not, so the
    browser gets 0 to 4 only, without ``close_fds``."""
    def move():
        high = [fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 10) for fd in (commands, replies)]
        os.dup2(high[0], 3)
        os.dup2(high[1], 4)
    return move


class BrowserError(RuntimeError):
    """The browser answered a command with an error, or went away."""


class Chromium:
    """A headless Chromium process and the pipe to it; ``close()`` ends it
    and removes its temporary profile."""

    def __init__(self, binary):
        self.binary = binary
        self.profile = tempfile.mkdtemp(prefix="deathsphere-view-profile-")
        # what the browser says on stderr, kept for a failure's message (a
        # file, not a pipe: a pipe nobody reads would stall it when full)
        self._log = tempfile.TemporaryFile()
        commands_r, self._commands = os.pipe()      # we write, the browser reads (its fd 3)
        self._replies, replies_w = os.pipe()        # the browser writes (its fd 4), we read
        try:
            self.process = subprocess.Popen(
                [binary, *FLAGS, f"--user-data-dir={self.profile}", "--remote-debugging-pipe", "about:blank"],
                preexec_fn=_onto_3_and_4(commands_r, replies_w), close_fds=False, stdin=subprocess.DEVNULL,
                stdout=subprocess.DEVNULL, stderr=self._log, start_new_session=True)
        except BaseException:
            for fd in (self._commands, self._replies):
                os.close(fd)
            self._log.close()
            shutil.rmtree(self.profile, ignore_errors=True)
            raise
        finally:
            # the browser holds its own copies: a closed pipe then means it is gone
            os.close(commands_r)
            os.close(replies_w)
        self._buffer = b""
        self._next_id = 0
        self._events = []
        self.closed = False
        try:
            self.version = self.send("Browser.getVersion")["product"]
        except BaseException:
            self.close()
            raise

    # ---------------------------------------------------------------- the protocol
    def _write(self, message: dict):
        data = json.dumps(message).encode() + b"\0"
        while data:
            data = data[os.write(self._commands, data):]

    def _read(self, deadline: float) -> dict:
        while b"\0" not in self._buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                raise BrowserError(f"no answer from the browser in {TIMEOUT_S:.0f} s")
            ready, _, _ = select.select([self._replies], [], [], left)
            if ready:
                chunk = os.read(self._replies, 1 << 20)
                if not chunk:
                    raise BrowserError("the browser closed its pipe: " + self._stderr_tail())
                self._buffer += chunk
        message, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(message)

    def send(self, method: str, params: dict | None = None, session: str | None = None) -> dict:
        """A command's result (events that arrive meanwhile are kept)."""
        self._next_id += 1
        message = {"id": self._next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        self._write(message)
        deadline = time.monotonic() + TIMEOUT_S
        while True:
            reply = self._read(deadline)
            if reply.get("id") != self._next_id:
                if "method" in reply:
                    self._events.append(reply)
                continue
            if "error" in reply:
                raise BrowserError(f"{method}: {reply['error']}")
            return reply.get("result", {})

    def wait_for(self, event: str, session: str) -> dict:
        """The next ``event`` of a session (one that came already, or the next to come)."""
        deadline = time.monotonic() + TIMEOUT_S
        while True:
            for i, message in enumerate(self._events):
                if message["method"] == event and message.get("sessionId") == session:
                    del self._events[i]
                    return message.get("params", {})
            self._events.append(self._read(deadline))

    def _forget(self, session: str):
        self._events = [m for m in self._events if m.get("sessionId") != session]

    # ---------------------------------------------------------------- a page
    def dom(self, url: str, budget_ms: int, size: tuple[int, int] | None = None) -> str:
        """The page's DOM (doctype and markup, as ``--dump-dom`` prints it)
        after ``budget_ms`` of virtual time; ``size`` (width, height) [CSS
        px] the viewport it gets (the browser's default window without)."""
        target = self.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        try:
            if size is not None:
                width, height = size
                self.send("Emulation.setDeviceMetricsOverride",
                          {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False}, session)
            # paused while the page is fetched, as the command line's budget is
            self.send("Emulation.setVirtualTimePolicy", {"policy": "pause"}, session)
            self.send("Page.navigate", {"url": url}, session)
            self.send("Emulation.setVirtualTimePolicy",
                      {"policy": "pauseIfNetworkFetchesPending", "budget": budget_ms}, session)
            self.wait_for("Emulation.virtualTimeBudgetExpired", session)
            result = self.send("Runtime.evaluate", {"expression": DOM, "returnByValue": True}, session)
            if "exceptionDetails" in result:
                raise BrowserError(f"reading the DOM of {url}: {result['exceptionDetails']}")
            return result["result"]["value"] + "\n"
        finally:
            self.send("Target.closeTarget", {"targetId": target})
            self._forget(session)

    # ---------------------------------------------------------------- the end
    def _stderr_tail(self) -> str:
        self._log.seek(0)
        return self._log.read().decode(errors="replace")[-2000:]

    def close(self):
        """Ask the browser to quit (it closes every tab and helper process),
        end what is left of its process group, and remove its profile."""
        if self.closed:
            return
        self.closed = True
        try:
            try:
                self._write({"id": self._next_id + 1, "method": "Browser.close", "params": {}})
            except OSError:
                pass                                  # gone already
            # the browser closes its end of the pipe as it exits
            deadline = time.monotonic() + 10
            try:
                while select.select([self._replies], [], [], max(deadline - time.monotonic(), 0))[0]:
                    if not os.read(self._replies, 1 << 20):
                        break
            except OSError:
                pass
            # exited, but not reaped yet (WNOWAIT): its process id, the
            # group's, cannot be taken by another process meanwhile
            while (os.waitid(os.P_PID, self.process.pid, os.WEXITED | os.WNOWAIT | os.WNOHANG) is None
                   and time.monotonic() < deadline):
                time.sleep(0.01)
            # its helpers share its process group (a session of its own):
            # none may outlive the test session
            try:
                os.killpg(self.process.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            self.process.wait(timeout=10)
        finally:
            for fd in (self._commands, self._replies):
                os.close(fd)
            self._log.close()
            shutil.rmtree(self.profile, ignore_errors=True)
