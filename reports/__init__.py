"""What the app reports about a scene: every computed value by name and the JSON the command
line prints (``values``), the textbook's printed answers beside the exact ones
(``textbook``), and a missing figure fitted to the printed values (``fitting``)."""
