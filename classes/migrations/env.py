"""Alembic's environment for the class store: the connection comes from
``classes.store.migrate`` (the app's and the command line's engine), never from a file."""

from alembic import context

from classes.store import metadata

connection = context.config.attributes["connection"]
context.configure(connection=connection, target_metadata=metadata,
                  render_as_batch=connection.dialect.name == "sqlite")
with context.begin_transaction():
    context.run_migrations()
