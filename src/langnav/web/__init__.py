"""The web app: chat, live map, plan progress and the stop button (FastAPI)."""
