# What accuracy costs in time (issue 6): being written.
accuracy:
	@echo "accuracy: not implemented yet (issue 6: what accuracy costs in time)" >&2; exit 2
