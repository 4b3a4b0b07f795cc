function r = periodic_orbit_impact_mass_velocity_after(M, K, C, m, e, d, F0, X_b, Omega, phi)
% PERIODIC_ORBIT_IMPACT_MASS_VELOCITY_AFTER  Impact-mass velocity U after the first impact [m/s], Eq. F3 (derived here, beyond the paper).
%
%   r = periodic_orbit_impact_mass_velocity_after(M, K, C, m, e, d, F0, X_b, Omega, phi)
%
% Arguments (scalars or arrays of compatible sizes, SI units):
%   M: Main mass M [kg]
%   K: Main stiffness K [N/m]
%   C: Main damping C (underdamped) [N s/m]
%   m: Impact mass m [kg]
%   e: Coefficient of restitution e [1]
%   d: Total clearance d [m]
%   F0: Force amplitude F0 on the main mass [N]
%   X_b: Base-motion amplitude X_b [m]
%   Omega: Forcing frequency Ω [rad/s]
%   phi: Forcing phase at the first impact φ [rad]
%
% Returns an array of the broadcast size; NaN where the result is not real.
% U = U = - \frac{M \Omega \left(d + \frac{2 \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{2 \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} + \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} + 1 + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)} - \frac{\left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}\right)}{\pi M \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} + \pi M \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} + \pi M \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) + \pi M - \frac{\pi M \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \frac{4 \Omega m e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}}
%
% Generated by derive/periodic_orbit.py through derive/templates/octave/kernel.m.j2.
% Do not edit by hand: change the derivation and run `python -m derive`.
% Mirrors symimpact.generated.periodic_orbit.impact_mass_velocity_after; operations: 84.
  x_0 = F0 + K.*X_b;
  x_1 = Omega.^2;
  x_2 = K - M.*x_1;
  x_3 = C.^2;
  x_4 = x_1.*x_3;
  x_5 = 2./(x_2.^2 + x_4);
  x_6 = pi./Omega;
  x_7 = 1./M;
  x_8 = C.*x_7/2;
  x_9 = exp(-x_6.*x_8);
  x_10 = sqrt(K.*x_7 - x_3./(4*M.^2));
  x_11 = x_10.*x_6;
  x_12 = cos(x_11);
  x_13 = sin(x_11);
  x_14 = x_13./x_10;
  x_15 = x_14.*x_9;
  x_16 = x_15.*x_8;
  x_17 = x_9.*(x_12 + x_14.*x_8);
  x_18 = x_12.*x_9 - x_16;
  x_19 = x_15.*(-x_17.*x_8 + x_9.*(-x_10.*x_13 + x_12.*x_8));
  x_20 = pi*M;
  x_21 = x_18.*x_20;
  r = -M.*Omega.*(d + x_5.*(X_b.*x_4 + x_0.*x_2).*cos(phi) + x_5.*(-C.*Omega.*X_b.*x_2 + C.*Omega.*x_0).*sin(phi)).*(x_12.*x_9 - x_16 + x_17.*x_18 + x_17 - x_19 + 1)./(4*Omega.*m.*x_15 + x_17.*x_20 + x_17.*x_21 - x_19.*x_20 + x_20 + x_21);
  r = r + zeros(size(M + K + C + m + e + d + F0 + X_b + Omega + phi));
  if ~isreal(r)
    r(imag(r) ~= 0) = NaN;
    r = real(r);
  end
end
