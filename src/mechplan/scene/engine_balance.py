"""Parse an engine scene's ``[balance]`` table into a :class:`BalanceSpec`."""

from __future__ import annotations

from ..model.engine_balance import BalanceSpec
from .reader import Table

KEYS = ("throw_spacing", "throw_positions", "orders", "counterweight_share",
        "counterweight_radius", "balance_shafts")


def parse_balance(t: Table, throws: int) -> BalanceSpec:
    """The balancing inputs; ``throws``: the number of crank throws (pins) of the engine."""
    t.check_keys(KEYS)
    if t.has("throw_spacing") and t.has("throw_positions"):
        raise t.error("throw_positions", "give either throw_spacing or throw_positions, not both")
    positions = None
    if t.has("throw_spacing"):
        a = t.quantity("throw_spacing", "length", required=True, positive=True)
        assert a is not None
        positions = tuple(i * a for i in range(throws))
    elif t.has("throw_positions"):
        raw = t.raw("throw_positions")
        if not isinstance(raw, list) or len(raw) != throws:
            raise t.error("throw_positions", f"expected one axial position per crank throw "
                          f"({throws}), e.g. [\"0 mm\", \"90 mm\", …] (got {raw!r})")
        positions = tuple(t.value_quantity(v, f"throw_positions[{i}]", "length")
                          for i, v in enumerate(raw))
    orders = t.raw("orders", 6)
    if not isinstance(orders, int) or isinstance(orders, bool) or not 2 <= orders <= 24:
        raise t.error("orders", f"must be a whole number from 2 to 24 (got {orders!r})")
    share = t.quantity("counterweight_share", "dimensionless", 0.5)
    assert share is not None
    if not 0.0 <= share <= 1.0:
        raise t.error("counterweight_share", f"the share of the reciprocating mass balanced by the "
                      f"counterweights must lie in [0, 1] (got {share:g})")
    radius = t.quantity("counterweight_radius", "length", positive=True)
    shafts = t.raw("balance_shafts", False)
    if not isinstance(shafts, bool):
        raise t.error("balance_shafts", f"expected true or false (got {shafts!r})")
    return BalanceSpec(positions, orders, share, radius, shafts)
