-- wrk script: POST /api/v1/envmaps/{id}/samples (the id is in the URL) for 64 samples as JSON.
wrk.method = "POST"
wrk.headers["Content-Type"] = "application/json"
wrk.body = '{"count": 64, "seed": 1}'
