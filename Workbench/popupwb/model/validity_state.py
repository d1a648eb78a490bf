"""A card's validity verdict: the states of its Validity property and how a verdict is recorded.

Imports nothing: the features record and reset verdicts through it, below everything that checks.
"""

# States of a card's Validity property (stored in files: never rename them). Valid, the older
# boolean, stays as Validity == VALID for scripts and files that read it.
NOT_CHECKED, VALID, INVALID = "NotChecked", "Valid", "Invalid"
VALIDITY_STATES = [NOT_CHECKED, VALID, INVALID]


def record_verdict(obj, state, diagnostics=()):
    """Writes the verdict `state` (one of VALIDITY_STATES) into obj.Validity, when it has one,
    obj.Valid and obj.Diagnostics, each only when it changes."""
    if "Validity" in obj.PropertiesList and obj.Validity != state:
        obj.Validity = state
    if obj.Valid != (state == VALID):
        obj.Valid = state == VALID
    if list(obj.Diagnostics) != list(diagnostics):
        obj.Diagnostics = list(diagnostics)


def verdict_of_old_file(obj):
    """The Validity of an object saved before it had one: Valid was True only after a passing
    check, and an invalid verdict always came with findings; anything else was never checked (or
    its verdict was dropped when the design changed)."""
    if obj.Valid:
        return VALID
    return INVALID if list(obj.Diagnostics) else NOT_CHECKED
