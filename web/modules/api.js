// The page's one way to call the server: JSON requests with the tab's bearer token, and errors
// as Error objects carrying the server's {"error":{code,message,path}} and the HTTP status.

// The bearer token of a server run with --token: typed once, kept for this tab only
// (sessionStorage), sent with every request.
export function authHeaders() {
  const token = sessionStorage.getItem('fsdb-token');
  return token ? { Authorization: `Bearer ${token}` } : {};
}

// An answer of 400 or more: `status` and `code` let a caller tell a 412 (someone else wrote
// first) from other failures.
export class ApiError extends Error {
  constructor(status, error) {
    super(error ? `${error.message}${error.path ? ` (${error.path})` : ''}` : `HTTP ${status}`);
    this.status = status;
    this.code = error ? error.code : '';
  }
}

async function send(path, options) {
  const response = await fetch(path, {
    ...options,
    headers: {
      ...(options.body && typeof options.body === 'string' ? { 'Content-Type': 'application/json' } : {}),
      ...authHeaders(),
      ...(options.headers || {}),
    },
  });
  if (!response.ok) {
    const body = await response.json().catch(() => null);
    throw new ApiError(response.status, body && body.error);
  }
  return response;
}

// A JSON answer.
export async function api(path, options = {}) {
  return (await send(path, options)).json().catch(() => null);
}

// A binary answer (mesh files), as an ArrayBuffer.
export async function apiBytes(path, options = {}) {
  return (await send(path, options)).arrayBuffer();
}
