# What the Python tests compare reports with: the title, every table's
# columns and every figure's pixels exactly (NaN equal to NaN: a cell that
# does not apply).
import numpy as np


def assert_same_report(a, b):
    assert a.title == b.title and list(a.tables) == list(b.tables)
    for name, table in a.tables.items():
        assert list(table) == list(b.tables[name]), name
        for key, values in table.items():
            if isinstance(values, np.ndarray):
                assert np.array_equal(values, b.tables[name][key], equal_nan=True), (name, key)
            else:
                assert values == b.tables[name][key], (name, key)
    assert [f.file for f in a.figures] == [f.file for f in b.figures]
    assert all(np.array_equal(x.image, y.image) for x, y in zip(a.figures, b.figures))
