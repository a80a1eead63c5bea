"""rosgrade's node runtime shared by both client libraries; on a node's import path as a folder, not a package."""
