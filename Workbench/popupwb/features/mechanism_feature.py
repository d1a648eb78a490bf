"""MechanismFeature: base of the pop-up mechanism features (tent, step, v-fold, box fold...).

A mechanism stands on a base patch pair (HostPair) offered by its Host: the card's central fold or
a pair a box fold offers. Its parameters are properties; the card's scaffold
(popupwb.model.card_scaffold) calls the popupcore generator with them, and execute() shows this mechanism's own patches of the
card posed at the card's FoldAngle. A parameter the generator refuses puts only this feature (and
what is nested on it) in error, with the core's message naming the property, and empties its
shape: no stale patches on screen. The card shows only its pages, so these are the only faces of
this mechanism: selecting or hiding it acts on them.

Dependencies: every mechanism links its root card (hidden `Card`), so FreeCAD recomputes it after
the card when FoldAngle changes; a changed parameter touches the card (it may move every mechanism
built after this one, and it resets the card's validity verdict), and so the whole card follows. Subclass module paths, class names and property names are
stored in .FCStd files: never rename them.
"""

import contextlib
import math


from popupwb import mechanism_catalogue
from popupwb.features.no_stale_shape import clears_shape_on_error
from popupwb.features.one_line_errors import one_line_errors
from popupwb.model import card_scaffold, profile_storage
from popupwb.profiles import editing
from popupwb.stateless_proxy import StatelessProxy
from popupwb.view_provider_by_name import attach_view_provider

VERSION = "1"

_PROPERTY_TYPES = {
    "length": "App::PropertyDistance",
    "angle": "App::PropertyAngle",
    "bool": "App::PropertyBool",
    "integer": "App::PropertyInteger",
}

# Objects whose properties this module is writing itself (during execute): no touching the card.
_QUIET = set()


@contextlib.contextmanager
def _quiet(obj):
    key = (obj.Document.Name, obj.Name)
    _QUIET.add(key)
    try:
        yield
    finally:
        _QUIET.discard(key)


def _restoring(obj):
    return "Restore" in obj.State or obj.Document.Restoring


def is_mechanism(obj):
    """True for document objects driven by a MechanismFeature subclass."""
    return card_scaffold.is_mechanism(obj)


class MechanismFeature(StatelessProxy):
    """Proxy of a Part::FeaturePython mechanism. Subclasses set the class attributes below."""

    IS_MECHANISM = True
    # popupwb.viewproviders module and class, imported only in the GUI (view_provider_by_name)
    VIEW_PROVIDER = ("mechanism_viewprovider", "MechanismViewProvider")
    KIND = None  # the core catalogue's kind, e.g. "tent_fold": subclasses set only this, and
    # the catalogue's row gives the attributes below.
    TYPE = None  # "PopUp::TentFold"
    GROUP = "Mechanism"  # property group of the parameters: the kind's title
    PARAMS = None  # name of the popupcore params class, e.g. "TentFoldParams"
    GENERATOR = None  # name of the popupcore generator, e.g. "add_tent_fold"
    PARAMETERS = ()  # mechanism_catalogue.Parameter tuples, in the order the task panel shows
    OFFERS = ()  # parts of the base patch pairs it offers: pair names are "<Label>.<part>"
    OUTPUTS = ()  # (name, doc) of read-only derived length properties
    FIXED_FIELDS = {}  # params fields a design may state with these values only

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if cls.KIND is None:
            return
        row = mechanism_catalogue.entry(cls.KIND)
        cls.TYPE = f"PopUp::{row.feature}"
        cls.GROUP = row.title
        cls.PARAMS = row.params
        cls.GENERATOR = row.generator
        cls.PARAMETERS = mechanism_catalogue.parameters(cls.KIND)
        cls.OFFERS = tuple(row.offers)
        cls.FIXED_FIELDS = dict(row.fixed)

    def __init__(self, obj):
        obj.Proxy = self
        self.add_properties(obj)

    # --- properties -------------------------------------------------------------------------

    def add_properties(self, obj):
        """Adds every property that is missing, so files written by older versions upgrade."""
        have = set(obj.PropertiesList)
        if "Host" not in have:
            obj.addProperty(
                "App::PropertyLink",
                "Host",
                "Placement on host",
                "The card or mechanism this one stands on",
            )
        if "HostPair" not in have:
            obj.addProperty(
                "App::PropertyEnumeration",
                "HostPair",
                "Placement on host",
                "Base patch pair of the host this mechanism stands on",
            )
        if "Card" not in have:
            obj.addProperty(
                "App::PropertyLink",
                "Card",
                "Placement on host",
                "The card at the root of the Host chain (set automatically; it makes FreeCAD "
                "recompute this mechanism after the card)",
            )
            obj.setEditorMode("Card", 2)
        for p in self.PARAMETERS:
            if p.name not in have:
                obj.addProperty(_PROPERTY_TYPES[p.kind], p.name, self.GROUP, p.doc)
                setattr(obj, p.name, p.default)
        for name, doc in self.OUTPUTS:
            if name not in have:
                obj.addProperty("App::PropertyDistance", name, self.GROUP, doc)
                obj.setEditorMode(name, 1)
                obj.setPropertyStatus(name, "Output")
        profile_storage.add_properties(obj)
        if "Version" not in have:
            obj.addProperty(
                "App::PropertyString", "Version", "Base", "Version of this object's properties"
            )
            obj.Version = VERSION
            obj.setEditorMode("Version", 1)

    def parameter_values(self, obj):
        """Plain values of the parameters (mm, degrees, bools): part of the design key."""
        values = []
        for p in self.PARAMETERS:
            value = getattr(obj, p.name)
            if p.kind == "bool":
                values.append(bool(value))
            elif p.kind == "integer":
                values.append(int(value))
            else:
                values.append(float(value.Value))
        return values

    def parameters(self, obj):
        """The popupcore params object from the properties (lengths in mm, angles in radians)."""
        return self.core_parameters(self.parameter_values(obj), obj.Label)

    @classmethod
    def core_parameters(cls, values, label):
        """The popupcore params object from plain `values` in PARAMETERS order (mm, degrees);
        `label` names the object in errors."""
        from popupwb.core import popupcore

        params = getattr(popupcore, cls.PARAMS)()
        for p, value in zip(cls.PARAMETERS, values):
            if p.kind == "integer" and not -(2**31) <= value < 2**31:
                # The core counts in 32 bits: name the property rather than fail in the binding.
                raise ValueError(f"{label}: {p.name} = {value}, must be below 2147483648")
            setattr(params, p.field, math.radians(value) if p.kind == "angle" else value)
        return params

    def generate(self, obj, scaffold, pair):
        """Adds this mechanism to `scaffold` on `pair` (popupcore.MechanismParts); DesignError
        when a parameter is out of range, and then nothing is added."""
        from popupwb.core import popupcore

        return getattr(popupcore, self.GENERATOR)(scaffold, pair, self.parameters(obj), obj.Label)

    @classmethod
    def fitted_parameters(cls, pair):
        """Parameter values (property name -> value) that fit the base patch pair `pair`: what a
        new mechanism starts with. Subclasses scale them to the pair's length and depths."""
        return {}

    def update_outputs(self, obj, built):
        """Writes derived read-only properties after a build (subclasses)."""
        return None

    # --- FreeCAD callbacks ------------------------------------------------------------------

    def onDocumentRestored(self, obj):
        self.add_properties(obj)
        attach_view_provider(obj)  # saved headless: it has none yet

    def onChanged(self, obj, prop):
        if _restoring(obj) or not hasattr(obj, "Version"):
            return
        if (obj.Document.Name, obj.Name) in _QUIET:
            return
        if prop == "Host":
            old_card = obj.Card
            self.follow_host(obj)
            if old_card is not None and old_card is not obj.Card:
                old_card.touch()  # its other mechanisms move and its verdict is stale
        if prop in ("ProfileSketch", "ProfilePart", "ProfileMode"):
            self.remember_profile_reference(obj)
        if (
            prop in ("Host", "HostPair", "Label")
            or prop in {p.name for p in self.PARAMETERS}
            or prop in profile_storage.PROPERTIES
        ):
            # Every mechanism after this one may move, and the card's verdict is for another design:
            # recompute the card, and through the Card links all its mechanisms.
            card = obj.Card
            if card is not None:
                card.touch()

    @staticmethod
    def drop_stale_verdict(card, built):
        """An edited ProfileSketch changes the design through this mechanism, without touching
        the card: its verdict, for the design before, is dropped here as the card would."""
        from popupwb.model import validity_state

        checked = getattr(card, "CheckedDesign", None)
        if checked is not None and checked != built.digest:
            if getattr(card, "Validity", validity_state.NOT_CHECKED) != validity_state.NOT_CHECKED:
                validity_state.record_verdict(card, validity_state.NOT_CHECKED)

    def remember_profile_reference(self, obj):
        """The sketch's part without a reference size gets its current one: Scale mode scales
        from the size the outline was drawn for."""
        part = (obj.ProfilePart or "").strip()
        if obj.ProfileSketch is None or not part or obj.Card is None:
            return
        try:
            if profile_storage.stored(obj).get(part, {}).get("reference") is None:
                editing.record_reference(obj, part, card_scaffold.for_card(obj.Card))
        except ValueError:
            pass  # a broken Profiles property: execute() reports it

    def unsetupObject(self, obj):
        # Removed from the document: the mechanisms after it move, the card's verdict is stale.
        card = getattr(obj, "Card", None)
        if card is not None:
            try:
                card.touch()
            except (ReferenceError, RuntimeError):
                pass

    def follow_host(self, obj):
        """After Host changed: the Card links of this mechanism and of everything nested on it
        (their root card may have changed too), and the HostPair choices."""
        with _quiet(obj):
            set_choices(obj, card_scaffold.host_pair_names(obj.Host) if obj.Host else [])
        for other in obj.Document.Objects:
            if not card_scaffold.is_mechanism(other):
                continue
            try:
                card = card_scaffold.root_card(other)
            except ValueError:
                card = None  # execute() reports it
            if other.Card is not card:
                with _quiet(other):
                    other.Card = card

    @one_line_errors
    @clears_shape_on_error
    def execute(self, obj):
        card = card_scaffold.root_card(obj)  # ValueError names a bad Host
        if obj.Card is not card:
            raise ValueError(
                f"{obj.Label}: Card = {obj.Card.Label if obj.Card else 'empty'}, must be "
                f"{card.Label}, the card at the root of its Host chain (set Host again)"
            )
        built = card_scaffold.for_card(card)
        self.drop_stale_verdict(card, built)
        if built.card_error is None and obj.Host.Name in built.offered:
            with _quiet(obj):
                set_choices(obj, built.pair_names(obj.Host.Name))
        error = built.errors.get(obj.Name)
        if error:
            raise ValueError(error)
        if obj.Name not in built.patches:
            raise ValueError(
                f"{obj.Label}: not part of {card.Label}'s scaffold (Host = "
                f"{obj.Host.Label}); recompute the document"
            )
        angle = card.FoldAngle.Value
        thickness = card.PaperThickness.Value if card.Thickened else 0.0
        try:
            shape = built.own_shape(obj.Name, angle, thickness)
        except ValueError as error:
            raise ValueError(
                f"{obj.Label}: the card {card.Label} at FoldAngle = {angle:g}° {error}"
            ) from error
        obj.Shape = shape
        obj.Placement = card.Placement  # the mechanism moves with its card
        with _quiet(obj):
            self.update_outputs(obj, built)


def set_choices(obj, names):
    """HostPair choices = `names`, keeping the current pair (or the pair with the same part after
    a rename of the host); written only when something changes."""
    current = obj.HostPair
    if list(obj.getEnumerationsOfProperty("HostPair") or []) != list(names):
        obj.HostPair = list(names)
    if not names:
        return
    if current in names:
        chosen = current
    else:
        part = (current or "").rsplit(".", 1)[-1]
        chosen = next((n for n in names if n.rsplit(".", 1)[-1] == part), names[0])
    if obj.HostPair != chosen:
        obj.HostPair = chosen
