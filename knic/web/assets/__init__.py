"""The page: index.html, app.js, map.js and style.css, served from memory by :mod:`knic.web.app`."""
