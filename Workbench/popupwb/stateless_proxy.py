"""Base class of PopUp proxies: they keep everything in properties and serialise nothing."""


class StatelessProxy:
    """Both state protocols: __getstate__/__setstate__ (FreeCAD 0.20) and dumps/loads (later)."""

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        return self.__setstate__(state)
