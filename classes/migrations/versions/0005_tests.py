"""A class may be a test (issue 66): one try per step, no hints and no "Show it", the verdicts
shown to its students once the lecturer closes it (``closed``). A deleted class keeps its row
(its code, marked ``deleted``; its students and checks are gone at once), so that a student's
link is told the class was deleted rather than that the code is unknown."""

import sqlalchemy as sa
from alembic import op

revision = "0005"
down_revision = "0004"


def upgrade() -> None:
    # plain ADD COLUMNs, never a batch: SQLite's batch copies the table and drops the old
    # one, and with foreign keys on, that drop cascades to every student and check
    op.add_column("classes", sa.Column("test", sa.Boolean, nullable=False, server_default=sa.false()))
    op.add_column("classes", sa.Column("closed", sa.DateTime(timezone=True)))
    op.add_column("classes", sa.Column("deleted", sa.DateTime(timezone=True)))


def downgrade() -> None:
    with op.batch_alter_table("classes") as batch:
        batch.drop_column("deleted")
        batch.drop_column("closed")
        batch.drop_column("test")
