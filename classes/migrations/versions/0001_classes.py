"""The class store's first schema: classes, students, checks."""

import sqlalchemy as sa
from alembic import op

revision = "0001"
down_revision = None


def upgrade() -> None:
    op.create_table(
        "classes",
        sa.Column("id", sa.Integer, primary_key=True),
        sa.Column("code", sa.String(6), nullable=False, unique=True),
        sa.Column("key_hash", sa.String(64), nullable=False),
        sa.Column("scene", sa.Text, nullable=False),
        sa.Column("method", sa.String(16), nullable=False),
        sa.Column("at", sa.Float),
        sa.Column("variants", sa.String(64)),
        sa.Column("created", sa.DateTime(timezone=True), nullable=False),
        sa.Column("expires", sa.DateTime(timezone=True), nullable=False))
    op.create_index("ix_classes_expires", "classes", ["expires"])
    op.create_table(
        "students",
        sa.Column("id", sa.String(32), primary_key=True),
        sa.Column("class_id", sa.Integer, sa.ForeignKey("classes.id", ondelete="CASCADE"),
                  nullable=False),
        sa.Column("nickname", sa.String(40), nullable=False),
        sa.Column("variant", sa.Integer),
        sa.Column("joined", sa.DateTime(timezone=True), nullable=False))
    op.create_index("ix_students_class_id", "students", ["class_id"])
    op.create_table(
        "checks",
        sa.Column("id", sa.Integer, primary_key=True),
        sa.Column("class_id", sa.Integer, sa.ForeignKey("classes.id", ondelete="CASCADE"),
                  nullable=False),
        sa.Column("student", sa.String(32), sa.ForeignKey("students.id", ondelete="CASCADE"),
                  nullable=False),
        sa.Column("step", sa.String(64), nullable=False),
        sa.Column("answer", sa.String(200), nullable=False),
        sa.Column("diagnosis", sa.String(16), nullable=False),
        sa.Column("try", sa.Integer, nullable=False),
        sa.Column("time", sa.DateTime(timezone=True), nullable=False),
        sa.Column("variant", sa.String(64)),
        sa.UniqueConstraint("student", "step", "try"))
    op.create_index("ix_checks_class_id", "checks", ["class_id"])


def downgrade() -> None:
    op.drop_table("checks")
    op.drop_table("students")
    op.drop_table("classes")
