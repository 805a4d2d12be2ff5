"""The app as an LTI 1.3 tool (docs/lti.md): a Moodle course's activity opens a task's
practice with no code to type, a class made by the launch, and the student's result goes
back to the course's gradebook. No Streamlit here: the routes are Starlette's, served
beside the app by ``asgi.py`` (``st.App``); the command line registers platforms."""
