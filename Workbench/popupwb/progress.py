"""Progress with Cancel for anything that can take more than half a second.

    from popupwb import progress

    report = progress.run("Card: checking validity", popupcore.check_validity, scaffold)

    with progress.Steps("Card: fitting", len(batches)) as steps:
        for batch in batches:
            results.append(steps.run(fit_batch, batch))  # Cancel stops between and within steps

In the GUI each call runs in a worker thread while the main thread keeps the window alive; once
the work has taken SHOW_AFTER_MS a modal progress dialog appears with Cancel. The work must not
touch FreeCAD documents or Qt (it runs off the main thread): pass it the core calls, which release
the GIL (popupcore.check_validity, layout_sheets, simulate_fold, ...).

Cancel raises Cancelled in the caller. A core call that takes a `cancel=` keyword stops for real:
pass `cancel=progress.CANCEL_FLAG` and the call gets a popupcore.CancelFlag that Cancel sets; the
core gives up at its next checkpoint (one fold-simulation step) and the worker is joined before
Cancelled is raised, so nothing runs on in the background. A call without one is abandoned: it
finishes in the background and its result is dropped (quitting FreeCAD waits for it).

Work that measures its own progress (popupcore.design_motion's MotionProgress) passes
`fraction=` a callable returning 0..1: the bar then follows it, read at every poll.

    progress.run("walk.bvh: designing", popupcore.design_motion, animation, options,
                 cancel=progress.CANCEL_FLAG, progress=meter, fraction=lambda: meter.value)

Headless (no GUI, or called off the main thread) run() is a plain call and Steps never cancels.
The dialog itself is popupwb.gui.progress_dialog's, which FreeCAD's GUI registers here as `dialogs`
when it loads the workbench (InitGui.py): this module imports neither Qt nor FreeCADGui.

FreeCAD's own FreeCAD.Base.ProgressIndicator (start(text, steps), next(canAbort), stop()) is not
used: it only advances when the main thread calls next(), which it cannot do while the main
thread waits for one long core call, and it aborts with Esc, not with a Cancel button.
"""

import threading
import time

SHOW_AFTER_MS = 500
POLL_SECONDS = 0.02
DIALOG_NAME = "PopUpProgress"  # objectName of the dialog (scripts and the GUI tests find it)

shown = []  # labels of the dialogs shown so far in this session (the GUI tests read it)
cancelled = []  # labels of the work cancelled so far (a command compares its length before/after)


FRACTION_STEPS = 1000  # the bar's range when it follows a fraction

# Stands for "a fresh popupcore.CancelFlag that Cancel sets" among a call's keyword arguments.
CANCEL_FLAG = object()

# The GUI's progress dialogs (popupwb.gui.progress_dialog.ProgressDialogs), registered when the GUI
# loads the workbench; None headless.
dialogs = None


class Cancelled(Exception):
    """The user pressed Cancel; the message says what was cancelled."""


def cancelled_message(label):
    return f"{label}: cancelled by the user"


def is_cancelled_message(text):
    return str(text).endswith(": cancelled by the user")


def _gui_thread():
    """True in the GUI's main thread, where a dialog can be shown."""
    if threading.current_thread() is not threading.main_thread():
        return False
    return dialogs is not None and dialogs.can_show()


class _Worker(threading.Thread):
    def __init__(self, function, args, kwargs):
        # Not a daemon: Python waits for an abandoned call before it exits (a daemon thread in
        # the core when the interpreter goes away aborts FreeCAD: "terminate called ...").
        super().__init__(name="PopUp progress worker", daemon=False)
        self.function, self.args, self.kwargs = function, args, kwargs
        self.result = self.error = None

    def run(self):
        try:
            self.result = self.function(*self.args, **self.kwargs)
        except BaseException as error:  # handed to the caller's thread
            self.error = error
        finally:
            self.function = self.args = self.kwargs = None


class Steps:
    """A context manager for work in `count` steps (0: unknown); steps.run(function, ...) runs one
    step with Cancel, steps.advance() counts a step done in the main thread and raises Cancelled
    when Cancel was pressed."""

    def __init__(self, label, count=0, fraction=None):
        self.label = label
        self.fraction = fraction  # a callable 0..1, or None: the bar counts steps
        self.count = FRACTION_STEPS if fraction is not None else count
        self.done = 0
        self.started = None
        self.dialog = None
        self.gui = _gui_thread()

    def __enter__(self):
        self.started = time.monotonic()
        return self

    def __exit__(self, *exc):
        if self.dialog is not None:
            dialogs.close(self.dialog)
            self.dialog = None
        return False

    def run(self, function, *args, **kwargs):
        flags = [key for key, value in kwargs.items() if value is CANCEL_FLAG]
        if not self.gui:
            kwargs.update({key: None for key in flags})  # headless: nothing cancels
            result = function(*args, **kwargs)
            self.done += 1
            return result
        flag = None
        if flags:
            from popupwb.core import popupcore

            flag = popupcore.CancelFlag()
            kwargs.update({key: flag for key in flags})
        worker = _Worker(function, args, kwargs)
        worker.start()
        while worker.is_alive():
            worker.join(POLL_SECONDS)  # waits with the GIL released
            try:
                self._poll()
            except Cancelled:
                if flag is not None:  # the core stops at its next checkpoint: wait for it
                    flag.cancel()
                    worker.join()
                raise
        self.done += 1
        self._update()
        if worker.error is not None:
            error, worker.error = worker.error, None
            raise error
        return worker.result

    def advance(self):
        self.done += 1
        if self.gui:
            self._update()
            self._poll()

    # --- the dialog -------------------------------------------------------------------------

    def _poll(self):
        if self.dialog is None:
            if (time.monotonic() - self.started) * 1000.0 < SHOW_AFTER_MS:
                return  # short work: no dialog, and no events (no input reaches the document)
            self._show()
        if self.fraction is not None:
            self.dialog.setValue(self._fraction_value())
        dialogs.process_events()
        if self.dialog.wasCanceled():
            cancelled.append(self.label)
            raise Cancelled(cancelled_message(self.label))

    def _show(self):
        value = self._fraction_value() if self.fraction is not None else min(self.done, self.count)
        self.dialog = dialogs.show(self.label, self.count, value)
        shown.append(self.label)

    def _fraction_value(self):
        value = float(self.fraction())
        return int(round(FRACTION_STEPS * min(max(value, 0.0), 1.0)))

    def _update(self):
        if self.dialog is not None and self.fraction is not None:
            self.dialog.setValue(self._fraction_value())
        elif self.dialog is not None and self.count:
            self.dialog.setValue(min(self.done, self.count))


def run(label, function, *args, fraction=None, **kwargs):
    """function(*args, **kwargs) with a progress dialog and Cancel after SHOW_AFTER_MS (GUI);
    raises Cancelled when cancelled. `label` names the object and the work ("Card: checking
    validity"); `fraction`, a callable returning 0..1 while the work runs, drives the bar."""
    with Steps(label, fraction=fraction) as steps:
        return steps.run(function, *args, **kwargs)
