"""The common base of bound results: the bound ``set``, whether it is ``certified``, its ``margin``.

Every bounding method returns a result object with method-specific details (the lambda of an
analytic update, the multipliers of an SDP, a lower bound ...). :class:`BoundResult` is what
they share, so that code comparing methods reads one set of names whatever produced the bound:

``set``
    The bound itself (an ``Ellipsoid``, a ``PseudoEllipsoid``, ...), or None when the method
    proved the bounded set empty. Each result keeps its own name for it as well
    (``.ellipsoid``, ``.bound``); ``set_attribute`` says which.
``certified``
    True when ``set`` is proven to contain the exact set of the inputs, their floats read as
    exact numbers (design principle 7): the analytic updates by their certified rounding
    margin, the SDP references by their float64 certificate. A result type whose method is not
    guaranteed sets it False and says so.
``margin``
    The relative outward enlargement applied to the computed member to make it certified
    (0 when none was needed); each result type's docstring says of what (shape or semi-axes).

It lives in ``sets`` so that ``analytic`` and ``optimal`` both import it without depending on
each other. The subclasses are frozen dataclasses, so the base holds no defaults (a dataclass
would take a base attribute as the default of a field of the same name): each subclass states
``set_attribute``, ``certified`` and ``margin`` itself, as a field, a class attribute or a
property, and a subclass that forgets one is refused when it is defined.
"""

from __future__ import annotations

from typing import Any, ClassVar

REQUIRED = ("set_attribute", "certified", "margin")


class BoundResult:
    """Base of the results of every bounding method (module docstring)."""

    #: Name of the attribute that holds the bound under its method's own name.
    set_attribute: ClassVar[str]
    certified: bool
    margin: float

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        annotated = set().union(*(vars(k).get("__annotations__", {}) for k in cls.__mro__[:-2]))
        missing = [name for name in REQUIRED if not hasattr(cls, name) and name not in annotated]
        if missing:
            raise TypeError(f"{cls.__name__} must define {', '.join(missing)} (BoundResult)")

    @property
    def set(self) -> Any:
        """The bound (None if the bounded set was proven empty)."""
        return getattr(self, self.set_attribute)
