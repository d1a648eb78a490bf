"""popupwb.progress without the GUI: a plain call, no thread, nothing to cancel (the dialog and
Cancel are tested in the GUI, tests/gui/run_gui_panel.py)."""

import threading

import pytest

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


def test_cancel_flag_headless_is_none(freecad):
    seen = []
    progress.run(
        "Card: checking", lambda cancel=0: seen.append(cancel), cancel=progress.CANCEL_FLAG
    )
    assert seen == [None]  # headless nothing cancels: the core gets no flag


def box_card(panel_pairs):
    from popupwb.core import popupcore

    size = popupcore.CardParams()
    size.width, size.depth = 200.0, 140.0
    card = popupcore.make_card(size)
    params = popupcore.BoxFoldParams()
    params.offset, params.width, params.panel_pairs = 40.0, 60.0, panel_pairs
    popupcore.add_box_fold(card, popupcore.central_fold(card), params, "Box")
    return card


def test_a_set_cancel_flag_stops_the_core_calls():
    from popupwb.core import popupcore
    from popupwb.sheets import export

    card = box_card(1)
    flag = popupcore.CancelFlag()
    assert not flag.cancelled
    assert popupcore.check_validity(card, cancel=flag).valid  # never set: runs to the end
    flag.cancel()
    assert flag.cancelled
    with pytest.raises(popupcore.Cancelled, match="the fold simulation: cancelled"):
        popupcore.check_validity(card, cancel=flag)
    with pytest.raises(popupcore.Cancelled, match="cancelled"):
        export.layout(card, paper="A3", cancel=flag)
    assert issubclass(popupcore.Cancelled, RuntimeError)
    assert not issubclass(popupcore.Cancelled, ValueError)  # not a bad design


def test_a_cancel_from_another_thread_stops_a_check_under_way():
    """The GUI's Cancel: the check runs in a worker thread (the GIL released), the main thread
    sets the flag 20 ms in. A box with 10 panel pairs checked at 5000 samples runs for seconds."""
    from popupwb.core import popupcore

    card = box_card(10)
    flag = popupcore.CancelFlag()
    outcome = []

    def work():
        try:
            outcome.append(popupcore.check_validity(card, samples=5000, cancel=flag).valid)
        except popupcore.Cancelled as error:
            outcome.append(str(error))

    worker = threading.Thread(target=work)
    worker.start()
    worker.join(0.02)
    flag.cancel()
    worker.join()
    assert outcome == ["the fold simulation: cancelled"] or outcome == [
        "the validity check: cancelled"
    ], outcome
