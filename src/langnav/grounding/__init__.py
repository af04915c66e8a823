"""Intent + map analysis + robot pose -> robot commands whose coordinates code computed."""
