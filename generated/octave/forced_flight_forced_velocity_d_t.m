function r = forced_flight_forced_velocity_d_t(t, M, K, C, F0, X_b, Omega, phi, x0, xdot0)
% FORCED_FLIGHT_FORCED_VELOCITY_D_T  ∂/∂t of: main-mass velocity ẋ(t) in forced free flight (its partial derivative in time since the last event) [m/s^2], Eq. F1 (derived here, beyond the paper).
%
%   r = forced_flight_forced_velocity_d_t(t, M, K, C, F0, X_b, Omega, phi, x0, xdot0)
%
% Arguments (scalars or arrays of compatible sizes, SI units):
%   t: Time since the last event [s]
%   M: Main mass M [kg]
%   K: Main stiffness K [N/m]
%   C: Main damping C (underdamped: C < 2√(KM)) [N s/m]
%   F0: Force amplitude F0 on the main mass [N]
%   X_b: Base-motion amplitude X_b [m]
%   Omega: Forcing frequency Ω [rad/s]
%   phi: Forcing phase at t = 0, φ [rad]
%   x0: Main-mass displacement at t = 0 [m]
%   xdot0: Main-mass velocity at t = 0 [m/s]
%
% Returns an array of the broadcast size; NaN where the result is not real.
% \partial \dot{x}(t) / \partial t = \partial \dot{x}(t) / \partial t = \begin{cases} \frac{- F_{0} \Omega^{3} t \sin{\left(\Omega t + \phi \right)} + 2 F_{0} \Omega^{2} \cos{\left(\Omega t + \phi \right)} + K \left(- \Omega^{3} X_{b} t \sin{\left(\Omega t + \phi \right)} + 2 \Omega^{2} X_{b} \cos{\left(\Omega t + \phi \right)} - 2 \Omega^{2} x_{0} \cos{\left(\Omega t \right)}\right) + \Omega^{2} \left(F_{0} \sin{\left(\phi \right)} + K X_{b} \sin{\left(\phi \right)} - 2 M \Omega \dot{x}_{0}\right) \sin{\left(\Omega t \right)}}{2 K} & \text{for}\: C = 0 \wedge K = M \Omega^{2} \\\frac{C^{2} \left(\left(x_{0} - \frac{\left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right) \cos{\left(t \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \right)} + \frac{\left(\frac{C \left(x_{0} - \frac{\left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right)}{2 M} + \frac{\Omega \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\Omega \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \dot{x}_{0}\right) \sin{\left(t \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}\right) e^{- \frac{C t}{2 M}}}{4 M^{2}} - \frac{C \left(- \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \left(x_{0} - \frac{\left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right) \sin{\left(t \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \right)} + \left(\frac{C \left(x_{0} - \frac{\left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right)}{2 M} + \frac{\Omega \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\Omega \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \dot{x}_{0}\right) \cos{\left(t \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \right)}\right) e^{- \frac{C t}{2 M}}}{M} - \frac{\Omega^{2} \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\Omega t + \phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\Omega^{2} \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\Omega t + \phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \left(- \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \left(\frac{C \left(x_{0} - \frac{\left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right)}{2 M} + \frac{\Omega \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\Omega \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \dot{x}_{0}\right) \sin{\left(t \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \right)} - \left(- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}\right) \left(x_{0} - \frac{\left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right) \cos{\left(t \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \right)}\right) e^{- \frac{C t}{2 M}} & \text{otherwise} \end{cases}
%
% Generated by derive/forced_flight.py through derive/templates/octave/kernel.m.j2.
% Do not edit by hand: change the derivation and run `python -m derive`.
% Mirrors symimpact.generated.forced_flight.forced_velocity_d_t; operations: 117.
  x_0 = Omega.*t;
  x_1 = phi + x_0;
  x_2 = cos(x_1);
  x_3 = Omega.^2;
  x_4 = 2*x_3;
  x_5 = sin(x_1);
  x_6 = Omega.^3.*t.*x_5;
  x_7 = sin(phi);
  x_8 = K.*X_b;
  x_9 = M.*x_3;
  x_10 = C.^2;
  x_11 = x_10.*x_3;
  x_12 = K - x_9;
  x_13 = 1./(x_11 + x_12.^2);
  x_14 = F0 + x_8;
  x_15 = x_13.*(-C.*Omega.*X_b.*x_12 + C.*Omega.*x_14);
  x_16 = x_13.*(X_b.*x_11 + x_12.*x_14);
  x_17 = 1./M;
  x_18 = C.*x_17;
  x_19 = x_18/2;
  x_20 = exp(-t.*x_19);
  x_21 = cos(phi);
  x_22 = x0 - x_15.*x_7 - x_16.*x_21;
  x_23 = M.^(-2);
  x_24 = K.*x_17 - x_10.*x_23/4;
  x_25 = sqrt(x_24);
  x_26 = t.*x_25;
  x_27 = sin(x_26);
  x_28 = x_25.*x_27;
  x_29 = cos(x_26);
  x_30 = -Omega.*x_15.*x_21 + Omega.*x_16.*x_7 + x_19.*x_22 + xdot0;
  x_31 = x_22.*x_29;
  r = pick((C == 0) & (K == x_9), (F0.*x_2.*x_4 - F0.*x_6 + K.*(2*X_b.*x_2.*x_3 - X_b.*x_6 - x0.*x_4.*cos(x_0)) + x_3.*(F0.*x_7 - 2*M.*Omega.*xdot0 + x_7.*x_8).*sin(x_0))./(2*K), x_10.*x_20.*x_23.*(x_31 + x_27.*x_30./x_25)/4 - x_15.*x_3.*x_5 - x_16.*x_2.*x_3 - x_18.*x_20.*(-x_22.*x_28 + x_29.*x_30) + x_20.*(-x_24.*x_31 - x_28.*x_30));
  r = r + zeros(size(t + M + K + C + F0 + X_b + Omega + phi + x0 + xdot0));
  if ~isreal(r)
    r(imag(r) ~= 0) = NaN;
    r = real(r);
  end
end

function r = pick(c, a, b)
% Element-wise selection: a where c holds, b elsewhere (the branch not taken is ignored, also
% where it is Inf or NaN).
  r = b + zeros(size(c)) + zeros(size(a));
  a = a + zeros(size(r));
  c = logical(c + zeros(size(r)));
  r(c) = a(c);
end
