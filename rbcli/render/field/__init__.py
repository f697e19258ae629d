"""The output of ``rbcli field-balance``: ``tables`` (the tables) and ``sheet`` (the job
sheet of ``--report``)."""
