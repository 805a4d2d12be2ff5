"""The app as an LTI 1.3 tool (issue 63): the platforms registered (a Moodle site each),
their deployments, the one-use login states, the resource links (each a class) and their
learners (a platform's pseudonymous ``sub`` → a student token, with what was last sent to
the platform's gradebook). No name or e-mail is stored."""

import sqlalchemy as sa
from alembic import op

revision = "0004"
down_revision = "0003"


def upgrade() -> None:
    op.create_table(
        "lti_platforms",
        sa.Column("id", sa.Integer, primary_key=True),
        sa.Column("issuer", sa.Text, nullable=False),
        sa.Column("client_id", sa.Text, nullable=False),
        sa.Column("auth_url", sa.Text, nullable=False),
        sa.Column("token_url", sa.Text, nullable=False),
        sa.Column("jwks_url", sa.Text, nullable=False),
        sa.Column("created", sa.DateTime(timezone=True), nullable=False),
        sa.UniqueConstraint("issuer", "client_id"))
    op.create_table(
        "lti_deployments",
        sa.Column("platform_id", sa.Integer,
                  sa.ForeignKey("lti_platforms.id", ondelete="CASCADE"), primary_key=True),
        sa.Column("deployment_id", sa.Text, primary_key=True))
    op.create_table(
        "lti_states",
        sa.Column("state", sa.String(64), primary_key=True),
        sa.Column("nonce", sa.String(64), nullable=False),
        sa.Column("platform_id", sa.Integer,
                  sa.ForeignKey("lti_platforms.id", ondelete="CASCADE"), nullable=False),
        sa.Column("expires", sa.DateTime(timezone=True), nullable=False, index=True))
    op.create_table(
        "lti_links",
        sa.Column("id", sa.Integer, primary_key=True),
        sa.Column("platform_id", sa.Integer,
                  sa.ForeignKey("lti_platforms.id", ondelete="CASCADE"), nullable=False),
        sa.Column("context_id", sa.Text, nullable=False),
        sa.Column("resource_link_id", sa.Text, nullable=False),
        sa.Column("class_code", sa.String(6), nullable=False),
        sa.Column("task", sa.Text, nullable=False),
        sa.Column("method", sa.String(16), nullable=False),
        sa.UniqueConstraint("platform_id", "context_id", "resource_link_id"))
    op.create_table(
        "lti_learners",
        sa.Column("id", sa.Integer, primary_key=True),
        sa.Column("link_id", sa.Integer, sa.ForeignKey("lti_links.id", ondelete="CASCADE"),
                  nullable=False),
        sa.Column("sub", sa.Text, nullable=False),
        sa.Column("student", sa.String(32), nullable=False),
        sa.Column("lineitem", sa.Text),  # AGS: where this learner's score goes (None: no grades)
        sa.Column("scored", sa.Integer, nullable=False, server_default="0"),  # last check sent
        sa.Column("due", sa.DateTime(timezone=True)),  # a failed send: when to try again
        sa.Column("failures", sa.Integer, nullable=False, server_default="0"),
        sa.UniqueConstraint("link_id", "sub"))


def downgrade() -> None:
    for table in ("lti_learners", "lti_links", "lti_states", "lti_deployments", "lti_platforms"):
        op.drop_table(table)
