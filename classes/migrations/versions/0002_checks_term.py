"""A check's named term: the one a "missing-term" answer left out (the class view names the
mistake most of a class makes, "14 left out a^k_C3C")."""

import sqlalchemy as sa
from alembic import op

revision = "0002"
down_revision = "0001"


def upgrade() -> None:
    with op.batch_alter_table("checks") as batch:  # (SQLite alters a table by copying it)
        batch.add_column(sa.Column("term", sa.String(64)))


def downgrade() -> None:
    with op.batch_alter_table("checks") as batch:
        batch.drop_column("term")
