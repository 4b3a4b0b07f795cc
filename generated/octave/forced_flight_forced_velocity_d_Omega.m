function r = forced_flight_forced_velocity_d_Omega(t, M, K, C, F0, X_b, Omega, phi, x0, xdot0)
% FORCED_FLIGHT_FORCED_VELOCITY_D_OMEGA  ∂/∂Omega of: main-mass velocity ẋ(t) in forced free flight (its partial derivative in forcing frequency Ω) [m/rad], Eq. F1 (derived here, beyond the paper).
%
%   r = forced_flight_forced_velocity_d_Omega(t, M, K, C, F0, X_b, Omega, phi, x0, xdot0)
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
% \partial \dot{x}(t) / \partial \Omega = \partial \dot{x}(t) / \partial \Omega = \begin{cases} - \frac{F_{0} t^{2} \sin{\left(\Omega t + \phi \right)}}{4 M} + \frac{F_{0} t \cos{\left(\Omega t + \phi \right)}}{4 M \Omega} - \frac{F_{0} \sin{\left(\Omega t \right)} \cos{\left(\phi \right)}}{4 M \Omega^{2}} - \frac{\Omega^{2} X_{b} t^{2} \sin{\left(\Omega t + \phi \right)}}{4} + \frac{\Omega X_{b} t \cos{\left(\Omega t + \phi \right)}}{4} - \frac{X_{b} \sin{\left(\Omega t \right)} \cos{\left(\phi \right)}}{4} & \text{for}\: C = 0 \wedge K = M \Omega^{2} \\- \frac{C \left(\left(- \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\left(2 C^{2} \Omega X_{b} - 2 M \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(2 C M \Omega^{2} X_{b} - C X_{b} \left(K - M \Omega^{2}\right) + C \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right) \cos{\left(t \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \right)} + \frac{\left(\frac{C \left(- \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\left(2 C^{2} \Omega X_{b} - 2 M \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(2 C M \Omega^{2} X_{b} - C X_{b} \left(K - M \Omega^{2}\right) + C \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right)}{2 M} + \frac{\Omega \left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\Omega \left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} + \frac{\Omega \left(2 C^{2} \Omega X_{b} - 2 M \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\Omega \left(2 C M \Omega^{2} X_{b} - C X_{b} \left(K - M \Omega^{2}\right) + C \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right) \sin{\left(t \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}\right) e^{- \frac{C t}{2 M}}}{2 M} - \frac{\Omega t \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\Omega t + \phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\Omega t \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\Omega t + \phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\Omega \left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\Omega t + \phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} + \frac{\Omega \left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\Omega t + \phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\Omega \left(2 C^{2} \Omega X_{b} - 2 M \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\Omega t + \phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\Omega \left(2 C M \Omega^{2} X_{b} - C X_{b} \left(K - M \Omega^{2}\right) + C \left(F_{0} + K X_{b}\right)\right) \cos{\left(\Omega t + \phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \left(- \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \left(- \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\left(2 C^{2} \Omega X_{b} - 2 M \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(2 C M \Omega^{2} X_{b} - C X_{b} \left(K - M \Omega^{2}\right) + C \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right) \sin{\left(t \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \right)} + \left(\frac{C \left(- \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\left(2 C^{2} \Omega X_{b} - 2 M \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(2 C M \Omega^{2} X_{b} - C X_{b} \left(K - M \Omega^{2}\right) + C \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right)}{2 M} + \frac{\Omega \left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\Omega \left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} + \frac{\Omega \left(2 C^{2} \Omega X_{b} - 2 M \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\Omega \left(2 C M \Omega^{2} X_{b} - C X_{b} \left(K - M \Omega^{2}\right) + C \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right) \cos{\left(t \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \right)}\right) e^{- \frac{C t}{2 M}} - \frac{\left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\Omega t + \phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\Omega t + \phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} & \text{otherwise} \end{cases}
%
% Generated by derive/forced_flight.py through derive/templates/octave/kernel.m.j2.
% Do not edit by hand: change the derivation and run `python -m derive`.
% Mirrors symimpact.generated.forced_flight.forced_velocity_d_Omega; operations: 155.
  x_0 = X_b/4;
  x_1 = cos(phi);
  x_2 = Omega.*t;
  x_3 = x_1.*sin(x_2);
  x_4 = phi + x_2;
  x_5 = cos(x_4);
  x_6 = sin(x_4);
  x_7 = t.^2.*x_6;
  x_8 = 1./M;
  x_9 = F0.*x_8/4;
  x_10 = Omega.^2;
  x_11 = M.*x_10;
  x_12 = C.^2;
  x_13 = x_10.*x_12;
  x_14 = K - x_11;
  x_15 = x_13 + x_14.^2;
  x_16 = 1./x_15;
  x_17 = x_16.*x_6;
  x_18 = 2*Omega;
  x_19 = x_12.*x_18;
  x_20 = F0 + K.*X_b;
  x_21 = -M.*x_18.*x_20 + X_b.*x_19;
  x_22 = Omega.*x_21;
  x_23 = X_b.*x_13 + x_14.*x_20;
  x_24 = C.*X_b;
  x_25 = x_14.*x_24;
  x_26 = C.*Omega.*x_20 - Omega.*x_25;
  x_27 = C.*x_20 + 2*x_11.*x_24 - x_25;
  x_28 = x_15.^(-2);
  x_29 = 4*M.*Omega.*x_14 - x_19;
  x_30 = x_28.*x_29;
  x_31 = x_23.*x_30;
  x_32 = Omega.*x_31;
  x_33 = C.*x_8/2;
  x_34 = exp(-t.*x_33);
  x_35 = sqrt(K.*x_8 - x_12./(4*M.^2));
  x_36 = t.*x_35;
  x_37 = sin(x_36);
  x_38 = x_1.*x_16;
  x_39 = sin(phi);
  x_40 = x_16.*x_39;
  x_41 = x_26.*x_30;
  x_42 = -x_1.*x_31 - x_21.*x_38 - x_27.*x_40 - x_39.*x_41;
  x_43 = cos(x_36);
  x_44 = -Omega.*x_1.*x_41 - Omega.*x_27.*x_38 + x_22.*x_40 + x_23.*x_40 - x_26.*x_38 + x_32.*x_39 + x_33.*x_42;
  r = pick((C == 0) & (K == x_11), F0.*t.*x_5.*x_8./(4*Omega) + Omega.*X_b.*t.*x_5/4 - x_0.*x_10.*x_7 - x_0.*x_3 - x_7.*x_9 - x_3.*x_9./x_10, Omega.*x_16.*x_27.*x_5 + Omega.*x_26.*x_28.*x_29.*x_5 - x_16.*x_2.*x_23.*x_5 + x_16.*x_26.*x_5 - x_17.*x_2.*x_26 - x_17.*x_22 - x_17.*x_23 - x_32.*x_6 - x_33.*x_34.*(x_42.*x_43 + x_37.*x_44./x_35) + x_34.*(-x_35.*x_37.*x_42 + x_43.*x_44));
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
