"""A new mechanism is placed beside the ones already on its host pair (thesis §4.2.2), says so when
there is no room, and a parameter that cannot fit the card is refused with its range.

Spans are checked against the features' own properties (a box sweeps from Offset - DepthGround to
Offset + Width + DepthGround closed, its end panels standing out; a step from Offset to Offset +
Width), against the card's width and against the core's placement_conflicts, and the placed card
must pass popupcore's validity check."""

import pytest

from freecad_documents import in_error, recompute_ok

A5_WIDTH = 148.0  # mm along the fold of an A5 card (its sheet's short side)


def box_span(box):
    reach = box.DepthGround.Value  # end panels, both present by default
    return box.Offset.Value - reach, box.Offset.Value + box.Width.Value + reach


def step_span(step):
    return step.Offset.Value, step.Offset.Value + step.Width.Value


def core_spans(popup, card):
    built = popup.card_scaffold.for_card(card)
    return {name: (p.sweep_from, p.sweep_to) for name, p in built.parts.items()}, built


def test_free_spans_are_what_no_span_covers(popup):
    Span = popup.placement.Span
    spans = [Span("a", -5.0, 10.0), Span("b", 15.0, 30.0), Span("c", 20.0, 40.0)]
    assert popup.placement.free_spans(100.0, spans) == [(10.0, 15.0), (40.0, 100.0)]
    assert popup.placement.largest_free_span(100.0, spans) == (40.0, 100.0)
    assert popup.placement.free_spans(50.0, [Span("d", 0.0, 60.0)]) == []
    assert popup.placement.largest_free_span(50.0, [Span("d", 0.0, 60.0)]) is None


def test_a_step_added_after_a_box_stands_beside_it(doc, popup):
    card = popup.make.make_card(doc, preset="A5")
    box = popup.make.make_box_fold(card)
    recompute_ok(doc, card, box)
    assert card.Width.Value == A5_WIDTH
    step = popup.make.make_step_fold(card)
    recompute_ok(doc, card, box, step)
    spans, built = core_spans(popup, card)
    # The core's spans are the features' own geometry.
    assert spans[box.Name] == pytest.approx(box_span(box))
    assert spans[step.Name] == pytest.approx(step_span(step))
    box_from, box_to = spans[box.Name]
    step_from, step_to = spans[step.Name]
    # At the host's fitted Offset (0.3 of the fold) the step would start inside the box's span.
    assert box_from < 0.3 * A5_WIDTH < box_to
    # Placed: inside the card, beside the box, centred in the larger free end of the fold.
    assert step_to <= box_from or step_from >= box_to, (spans[box.Name], spans[step.Name])
    assert 0.0 <= step_from and step_to <= A5_WIDTH
    gaps = [(0.0, box_from), (box_to, A5_WIDTH)]
    gap = max(gaps, key=lambda g: g[1] - g[0])
    assert gap[0] <= step_from and step_to <= gap[1]
    assert (step_from + step_to) / 2 == pytest.approx((gap[0] + gap[1]) / 2)
    assert popup.core.placement_conflicts(list(built.parts.values())) == []
    report = popup.validity.run_check(card)
    assert report["valid"] is True, list(card.Diagnostics)


@pytest.mark.parametrize(
    "kind",
    ["tent_fold", "v_fold", "v_box_fold", "rotation_arm", "horizontal_translation", "box_fold"],
)
def test_every_type_is_placed_beside_a_box(doc, popup, kind):
    card = popup.make.make_card(doc, preset="A5")
    box = popup.make.make_box_fold(card)
    added = getattr(popup.make, f"make_{kind}")(card)
    recompute_ok(doc, card, box, added)
    spans, built = core_spans(popup, card)
    (a_from, a_to), (b_from, b_to) = spans[box.Name], spans[added.Name]
    assert a_to <= b_from or b_to <= a_from, (spans[box.Name], spans[added.Name])
    assert 0.0 <= b_from and b_to <= A5_WIDTH
    assert popup.core.placement_conflicts(list(built.parts.values())) == []
    assert popup.validity.run_check(card)["valid"] is True, list(card.Diagnostics)


def test_steps_fill_the_fold_until_no_span_is_free(doc, popup):
    card = popup.make.make_card(doc, preset="A5")
    placed = []
    for _ in range(12):
        step = popup.make.make_step_fold(card)
        recompute_ok(doc, card, step)
        text, fits = popup.placement.span_report(step)
        if not fits:
            break
        placed.append(step)
    else:
        pytest.fail("twelve steps fitted on a 148 mm fold")
    late = step
    spans, built = core_spans(popup, card)
    assert len(placed) >= 3
    placed_parts = [built.parts[s.Name] for s in placed]
    assert popup.core.placement_conflicts(placed_parts) == []
    for step in placed:
        assert 0.0 <= spans[step.Name][0] and spans[step.Name][1] <= A5_WIDTH
    # The one with no room keeps its fitted values, and its panel line says what it overlaps
    # and the largest gap the others leave, too short for it.
    assert late.Offset.Value == pytest.approx(0.3 * A5_WIDTH)
    assert late.Width.Value == pytest.approx(0.4 * A5_WIDTH)
    edges = sorted(spans[s.Name] for s in placed)
    gaps = [(0.0, edges[0][0])] + [(a[1], b[0]) for a, b in zip(edges, edges[1:])]
    gap = max(gaps + [(edges[-1][1], A5_WIDTH)], key=lambda g: g[1] - g[0])
    assert gap[1] - gap[0] < 0.1 * 0.4 * A5_WIDTH / 0.8  # shorter than a tenth of a fitted step
    assert "overlaps " in text and f"largest free span {gap[0]:.1f}–{gap[1]:.1f} mm" in text


def test_no_free_span_on_a_fold_taken_end_to_end(doc, popup):
    card = popup.make.make_card(doc, preset="A5")
    wide = popup.make.make_step_fold(card, offset=0.0, width=A5_WIDTH)
    recompute_ok(doc, card, wide)
    from popupwb.features.tent_fold import TentFold

    fitted = {"Offset": 0.3 * A5_WIDTH, "Width": 0.4 * A5_WIDTH}
    result = popup.placement.place(TentFold, card, "central fold", fitted)
    assert result.no_free_span and result.values == fitted
    assert result.taken == [popup.placement.Span(wide.Label, 0.0, A5_WIDTH)]
    assert result.message("TentFold") == (
        "TentFold: no free span on central fold for it (none is left; 0–148.0 mm taken by "
        "StepFold 0.0–148.0 mm): it starts at its defaults and overlaps, so they may collide as "
        "the card folds (thesis §4.2.2); make room or move it"
    )
    tent = popup.make.make_tent_fold(card)
    recompute_ok(doc, card, tent)
    text, fits = popup.placement.span_report(tent)
    assert not fits and text.endswith("no free span left on central fold")
    # A caller who gives the Offset chose the spot: nothing is moved or reported.
    chosen = popup.placement.place(TentFold, card, "central fold", fitted, given={"Offset": 44.4})
    assert not chosen.no_free_span and chosen.values == fitted


def test_a_500_mm_box_on_a5_is_refused_with_its_range(doc, popup):
    card = popup.make.make_card(doc, preset="A5")
    box = popup.make.make_box_fold(card, width=500.0)
    doc.recompute()
    assert in_error(box) and not in_error(card)
    assert box.getStatusString() == (
        f"{box.Label}: Width = 500 mm, must be > 0 and <= {A5_WIDTH:g} mm "
        "(the length of central fold)"
    )
    # As for a negative value: the same one line, on the mechanism.
    box.Width = -5.0
    doc.recompute()
    assert box.getStatusString().startswith(f"{box.Label}: Width = -5 mm, must be > 0 and <= ")
    box.Width = 40.0
    recompute_ok(doc, card, box)
