"""A resource link whose launches name only the platform's line-items container (an
activity added by hand, without deep linking) gets a line item the tool makes there once
(issue 69): the container, the label the tool gives it, when a process last asked the
platform for it (one process at a time, again a minute after a failure), and the line item."""

import sqlalchemy as sa
from alembic import op

revision = "0006"
down_revision = "0005"


def upgrade() -> None:
    # plain ADD COLUMNs (see 0005: no batch copy of a table others point at)
    op.add_column("lti_links", sa.Column("lineitems", sa.Text))
    op.add_column("lti_links", sa.Column("label", sa.Text))
    op.add_column("lti_links", sa.Column("asked", sa.DateTime(timezone=True)))
    op.add_column("lti_links", sa.Column("lineitem", sa.Text))


def downgrade() -> None:
    for column in ("lineitem", "asked", "label", "lineitems"):
        op.drop_column("lti_links", column)
