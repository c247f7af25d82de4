"""Reading a results store (DIR/results.sqlite, docs/store.md) from Python.

Tables come back as pandas DataFrames when pandas is installed, as lists of
dicts otherwise. The store is opened read-only as `icpbench report` opens it:
with a writer's WAL file present, read through it; otherwise immutable, so
reading creates no -wal/-shm files and needs no write permission.
"""

import os
import sqlite3
import threading
from urllib.parse import quote

try:
    import pandas as _pd
except ImportError:  # plain records without pandas
    _pd = None

_KNOWN_SCHEMA_VERSIONS = {1, 2, 3}


class Store:
    """A results store, read-only. Use as a context manager or call close()."""

    def __init__(self, directory):
        path = os.path.join(os.fspath(directory), "results.sqlite")
        if not os.path.isfile(path):
            raise ValueError(f"{path}: no results store here (run `icpbench run SPEC --out "
                             f"{os.fspath(directory)}` first)")
        self.path = path
        self._db = None
        # One connection, any thread (a thread pool, a widget's callback):
        # its use is serialized here instead of refused by sqlite3.
        self._lock = threading.Lock()
        self._connect()
        try:
            version = self._db.execute(
                "SELECT value FROM meta WHERE key='schema_version'").fetchone()
        except sqlite3.DatabaseError as e:
            raise ValueError(f"{path}: not an icpbench results store ({e})") from None
        try:
            self.schema_version = int(version[0]) if version else None
        except (TypeError, ValueError):
            raise ValueError(f"{path}: not an icpbench results store (schema version "
                             f"{version[0]!r})") from None
        if self.schema_version not in _KNOWN_SCHEMA_VERSIONS:
            raise ValueError(f"{path}: schema version {self.schema_version} is not one this "
                             f"icpbench reads ({sorted(_KNOWN_SCHEMA_VERSIONS)})")

    def _state(self):
        """What says the file changed: its size and time, and whether a WAL exists."""
        stat = os.stat(self.path)
        return stat.st_size, stat.st_mtime_ns, os.path.exists(self.path + "-wal")

    def _connect(self):
        if self._db is not None:
            self._db.close()
        self._opened_state = self._state()
        mode = "mode=ro" if self._opened_state[2] else "immutable=1"
        # Autocommit (isolation_level None): sqlite3 would open a transaction
        # before a write it then refuses, and every later read would stay in
        # that snapshot, blind to new runs.
        self._db = sqlite3.connect(f"file:{quote(os.path.abspath(self.path))}?{mode}", uri=True,
                                   isolation_level=None, check_same_thread=False)
        # Read-only also for ATTACH, which would create the file it names.
        self._db.set_authorizer(
            lambda action, *_: sqlite3.SQLITE_DENY if action == sqlite3.SQLITE_ATTACH else sqlite3.SQLITE_OK)

    def _fresh(self):
        """The connection, opened again if a sweep wrote the store meanwhile:
        an immutable one would not see it."""
        if self._opened_state[2] is False and self._state() != self._opened_state:
            self._connect()
        return self._db

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        with self._lock:
            self._db.close()

    def query(self, sql, params=()):
        """Any SELECT on the store, as a DataFrame (or records). Raises ValueError
        on a bad query (and on any that would write)."""
        with self._lock:
            try:
                cursor = self._fresh().execute(sql, params)
                if cursor.description is None:
                    raise ValueError(f"{self.path}: query {sql!r} returns no columns (not a SELECT)")
                columns = [d[0] for d in cursor.description]
                rows = cursor.fetchall()
            except (sqlite3.Error, sqlite3.Warning) as e:
                raise ValueError(f"{self.path}: query {sql!r}: {e}") from None
        if _pd is not None:
            return _pd.DataFrame.from_records(rows, columns=columns)
        return [dict(zip(columns, row)) for row in rows]

    def _table(self, table, run_id):
        # A version-1 store has no property tables: no properties, as `report` reads it.
        if table.endswith("_properties") and self.schema_version == 1:
            step = "NULL AS step, " if table == "step_properties" else ""
            return self.query(f"SELECT NULL AS run_id, {step}NULL AS name, NULL AS type, "
                              "NULL AS value WHERE 0")
        if run_id is None:
            return self.query(f"SELECT * FROM {table}")
        return self.query(f"SELECT * FROM {table} WHERE run_id = ?", (run_id,))

    def runs(self):
        """One row per run: algorithm, problem, their parameters, status, metrics."""
        return self.query("SELECT * FROM runs ORDER BY id")

    def steps(self, run_id=None):
        """One row per step (of one run, or of all)."""
        return self._table("steps", run_id)

    def step_values(self, run_id=None):
        """Per step and reported variable: lo, hi and the truth."""
        return self._table("step_values", run_id)

    def step_properties(self, run_id=None):
        """What estimators report per step beyond the columns (name, type, value)."""
        return self._table("step_properties", run_id)

    def run_properties(self, run_id=None):
        """What estimators report per run (name, type, value)."""
        return self._table("run_properties", run_id)


def open(directory):  # noqa: A001 (icpbench.open mirrors `icpbench report DIR`)
    """Opens DIR/results.sqlite read-only."""
    return Store(directory)
