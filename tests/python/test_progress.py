"""popupwb.progress without the GUI: a plain call, no thread, nothing to cancel (the dialog and
Cancel are tested in the GUI, tests/gui/run_gui_panel.py)."""

import threading

from popupwb import progress


def test_run_is_a_plain_call_headless(freecad):
    threads = []

    def work(a, b=0):
        threads.append(threading.current_thread())
        return a + b

    assert progress.run("Card: adding", work, 2, b=3) == 5
    assert threads == [threading.main_thread()]  # no worker thread headless


def test_run_passes_exceptions_through_headless(freecad):
    def fail():
        raise ValueError("Card: Width = -1 mm, must be > 0")

    try:
        progress.run("Card: failing", fail)
    except ValueError as error:
        assert str(error) == "Card: Width = -1 mm, must be > 0"
    else:
        raise AssertionError("the error was swallowed")


def test_steps_count_without_a_dialog(freecad):
    with progress.Steps("Card: fitting", 3) as steps:
        results = [steps.run(lambda i=i: i * i) for i in range(3)]
        steps.advance()
    assert results == [0, 1, 4] and steps.done == 4 and steps.dialog is None


def test_cancelled_messages_name_the_work():
    message = progress.cancelled_message("Card: checking validity")
    assert message == "Card: checking validity: cancelled by the user"
    assert progress.is_cancelled_message(message)
    assert not progress.is_cancelled_message("Card: Width = -1 mm, must be > 0")
