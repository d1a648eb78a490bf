"""The fold player: steps a card's FoldAngle from open to closed and back on a QTimer, recomputing
at each tick, so the GUI stays responsive. PopUp_Animate and the card panel's Play button both run
it; one play runs at a time (play() stops the running one). The card's FoldAngle is restored at
the end. Not undoable (a view, not an edit).
"""

import FreeCAD

MESSAGE_PREFIX = "PopUp_Animate"  # what its messages start with: the command that plays
STEP_DEGREES = 3.0
STEP_MS = 30

_player = None  # the running Player, kept alive here


class Player:
    """Steps `card` through `angles` (degrees), one per timer tick, then restores its angle."""

    def __init__(self, card, angles, interval_ms=STEP_MS):
        from PySide import QtCore

        self.card = card
        self.angles = list(angles)
        self.original = card.FoldAngle.Value
        self.frames = 0
        self.lowest = self.original  # the smallest angle shown so far
        self.timer = QtCore.QTimer()
        self.timer.setInterval(interval_ms)
        self.timer.timeout.connect(self.step)

    def start(self):
        self.timer.start()

    def running(self):
        return self.timer.isActive()

    def step(self):
        try:
            if not self.angles:
                self.stop()
                return
            angle = self.angles.pop(0)
            self.card.FoldAngle = angle
            self.card.Document.recompute()
            self.frames += 1
            self.lowest = min(self.lowest, angle)
        except Exception as error:  # deleted card, closed document: stop instead of looping
            FreeCAD.Console.PrintError(f"{MESSAGE_PREFIX}: stopped: {error}\n")
            self.timer.stop()

    def stop(self):
        self.timer.stop()
        try:
            self.card.FoldAngle = self.original
            self.card.Document.recompute()
        except (ReferenceError, RuntimeError):
            pass


def sweep_angles(step=STEP_DEGREES):
    """180 down to 0 and back up to 180, in steps of `step` degrees."""
    count = max(1, int(round(180.0 / step)))
    down = [180.0 - 180.0 * i / count for i in range(count + 1)]
    return down + down[-2::-1]


def play(card, step=STEP_DEGREES, interval_ms=STEP_MS):
    """Starts playing `card` (stopping any running play); returns the Player."""
    global _player
    stop()
    _player = Player(card, sweep_angles(step), interval_ms)
    _player.start()
    return _player


def stop():
    """Stops the running play, if any; True when one was running."""
    global _player
    running = _player is not None and _player.running()
    if running:
        _player.stop()
    _player = None
    return running


def current_player():
    """The Player of the last play() (running or finished), None once stop() ran."""
    return _player
