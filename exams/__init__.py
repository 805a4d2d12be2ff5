"""Exam variants: the task's given numbers varied around the book's (``variation``), the
variants kept when they are good exercises with their answer keys (``variants``), a code per
student (``codes``) and printable A4 sheets (``sheets``)."""
