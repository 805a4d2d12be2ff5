"""A check's own id (issue 60): made where the check is made, so that "sent again" is the
same id and every other check is stored, whatever try it is. Existing checks get an id of
their own; an answer stored as JSON's non-standard NaN or Infinity becomes null (not a
number: the export is strict JSON)."""

import sqlalchemy as sa
from alembic import op

revision = "0003"
down_revision = "0002"


def upgrade() -> None:
    with op.batch_alter_table("checks") as batch:
        batch.add_column(sa.Column("check_id", sa.String(36)))
    op.execute("UPDATE checks SET check_id = 'stored-' || CAST(id AS VARCHAR(20))")
    op.execute("UPDATE checks SET answer = 'null' WHERE answer LIKE '%NaN%' "
               "OR answer LIKE '%Infinity%'")
    with op.batch_alter_table("checks") as batch:
        batch.alter_column("check_id", existing_type=sa.String(36), nullable=False)
        batch.create_unique_constraint("uq_checks_check_id", ["check_id"])


def downgrade() -> None:
    with op.batch_alter_table("checks") as batch:
        batch.drop_constraint("uq_checks_check_id", type_="unique")
        batch.drop_column("check_id")
