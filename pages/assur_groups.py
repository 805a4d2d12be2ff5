"""Chapter page placeholder (its issue is not done yet)."""

from ui.chapters import coming_soon

coming_soon("pages/assur_groups.py")
